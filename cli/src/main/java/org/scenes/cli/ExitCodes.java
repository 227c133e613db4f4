package org.scenes.cli;

/** Exit codes of every command. */
final class ExitCodes {
    static final int OK = 0;
    /** The work failed: bad input data, a failing plugin, an I/O error. */
    static final int FAILURE = 1;
    /** The command line was wrong: unknown option, bad value, unknown plugin name. */
    static final int USAGE = 2;

    private ExitCodes() {
    }
}
