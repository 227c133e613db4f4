package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

class ScenesCommandTest {
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        return Main.run(new PrintWriter(out), new PrintWriter(err), args);
    }

    @Test
    void anUnknownOptionIsAUsageErrorNamingTheOption() {
        assertEquals(ExitCodes.USAGE, run("--frobnicate"));
        assertTrue(err.toString().contains("Unknown option: '--frobnicate'"), err.toString());
    }

    @Test
    void aBadPluginDirectoryIsAUsageErrorWithoutStackTrace() {
        assertEquals(ExitCodes.USAGE, run("plugins", "--plugin-path", "/no/such/dir"));
        assertTrue(err.toString().contains("/no/such/dir"), err.toString());
        assertFalse(err.toString().contains("\tat "), "no stack trace without --verbose");
    }

    @Test
    void verbosePrintsTheStackTrace() {
        run("plugins", "--verbose", "--plugin-path", "/no/such/dir");
        assertTrue(err.toString().contains("\tat "), err.toString());
    }

    @Test
    void helpListsTheSubcommands() {
        assertEquals(ExitCodes.OK, run("--help"));
        assertTrue(out.toString().contains("plugins"), out.toString());
    }
}
