package org.scenes.cli;

import java.io.PrintWriter;
import java.util.Set;
import org.scenes.internal.files.AtomicOutput;

/** Entry point of the {@code scenes} launcher. */
public final class Main {
    private Main() {
    }

    /**
     * Commands whose outputs are worthless when interrupted: on Ctrl-C or SIGTERM their temporary
     * files are removed. Not the proxy, server or live players, which complete their logs then.
     */
    static final Set<String> ABANDONED_ON_INTERRUPT = Set.of("convert", "export", "validate", "tune", "experiment",
            "simulate", "bench", "replay", "stats", "show");

    public static void main(String[] args) {
        if (args.length > 0 && ABANDONED_ON_INTERRUPT.contains(args[0])
                && !ShutdownHooks.addOrRun(new Thread(AtomicOutput::abandonAll, "scenes-abandon-outputs"))) {
            return; // stopped while starting: nothing begun
        }
        int status;
        try {
            status = ScenesCommand.commandLine().execute(args);
        } catch (OutOfMemoryError e) {
            System.err.println("scenes: " + Limits.outOfMemoryMessage());
            status = ExitCodes.FAILURE;
        }
        System.exit(status);
    }

    /** Runs a command line with the given output streams and returns its exit code, for embedding and tests. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        var commandLine = ScenesCommand.commandLine();
        commandLine.setOut(out);
        commandLine.setErr(err);
        try {
            return commandLine.execute(args);
        } catch (OutOfMemoryError e) {
            err.println("scenes: " + Limits.outOfMemoryMessage());
            return ExitCodes.FAILURE;
        } finally {
            out.flush();
            err.flush();
        }
    }
}
