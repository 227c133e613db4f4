package org.scenes.cli;

import java.io.PrintWriter;

/** Entry point of the {@code scenes} launcher. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.exit(ScenesCommand.commandLine().execute(args));
    }

    /** Runs a command line with the given output streams and returns its exit code, for embedding and tests. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        var commandLine = ScenesCommand.commandLine();
        commandLine.setOut(out);
        commandLine.setErr(err);
        try {
            return commandLine.execute(args);
        } finally {
            out.flush();
            err.flush();
        }
    }
}
