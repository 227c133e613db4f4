package org.scenes.cli;

import picocli.CommandLine;

/** Exit codes of every command: picocli's, named for what they mean here. */
final class ExitCodes {
    static final int OK = CommandLine.ExitCode.OK;
    /** The work failed: bad input data, a failing plugin, an I/O error. */
    static final int FAILURE = CommandLine.ExitCode.SOFTWARE;
    /** The command line was wrong: unknown option, bad value, unknown plugin name. */
    static final int USAGE = CommandLine.ExitCode.USAGE;

    private ExitCodes() {
    }
}
