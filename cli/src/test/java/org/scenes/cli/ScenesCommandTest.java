package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ScenesCommandTest {
    private final CommandRunner cli = new CommandRunner();

    private int run(Object... args) {
        return cli.run(args);
    }

    @Test
    void anUnknownOptionIsAUsageErrorNamingTheOption() {
        assertEquals(ExitCodes.USAGE, run("--frobnicate"));
        assertTrue(cli.err().contains("Unknown option: '--frobnicate'"), cli.err());
    }

    @Test
    void aBadPluginDirectoryIsAUsageErrorWithoutStackTrace() {
        assertEquals(ExitCodes.USAGE, run("plugins", "--plugin-path", "/no/such/dir"));
        assertTrue(cli.err().contains("/no/such/dir"), cli.err());
        assertFalse(cli.err().contains("\tat "), "no stack trace without --verbose");
    }

    @Test
    void verbosePrintsTheStackTrace() {
        run("plugins", "--verbose", "--plugin-path", "/no/such/dir");
        assertTrue(cli.err().contains("\tat "), cli.err());
    }

    @Test
    void pluginsNamesTheFlagEachKindOfOptionIsGivenWith() {
        assertEquals(ExitCodes.OK, run("plugins"));
        assertTrue(cli.out().contains("--selector-option percent=..."), cli.out());
        assertFalse(cli.out().contains("--option percent="), "percent is a selector option: " + cli.out());
        assertTrue(cli.out().contains("--option space=..."), cli.out());
    }

    @Test
    void helpListsTheSubcommands() {
        assertEquals(ExitCodes.OK, run("--help"));
        assertTrue(cli.out().contains("plugins"), cli.out());
    }
}
