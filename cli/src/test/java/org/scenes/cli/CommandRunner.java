package org.scenes.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Arrays;

/** Runs {@code scenes} command lines in-process, keeping what the latest run printed. */
final class CommandRunner {
    private StringWriter out = new StringWriter();
    private StringWriter err = new StringWriter();

    /** Runs one command line (arguments as {@code toString()}) and returns its exit code. */
    int run(Object... args) {
        out = new StringWriter();
        err = new StringWriter();
        return Main.run(new PrintWriter(out, true), new PrintWriter(err, true),
                Arrays.stream(args).map(Object::toString).toArray(String[]::new));
    }

    /** Standard output of the latest run. */
    String out() {
        return out.toString();
    }

    /** Standard error of the latest run. */
    String err() {
        return err.toString();
    }
}
