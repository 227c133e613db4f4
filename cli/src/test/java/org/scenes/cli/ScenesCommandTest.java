package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
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

    @Test
    void aFileThatCannotBeReadIsNamedWithTheReason() {
        // root reads every file, so the denial is made here rather than by chmod
        assertEquals("/data/game.rcg: permission denied",
                ScenesCommand.message(new java.nio.file.AccessDeniedException("/data/game.rcg")));
        assertEquals("/data: Not a directory", ScenesCommand.message(
                new java.nio.file.FileSystemException("/data", null, "Not a directory")));
    }

    @Test
    void everyCommandAnswersHelpWithItsUsage() {
        for (String command : ScenesCommand.commandLine().getSubcommands().keySet()) {
            for (String flag : new String[] {"--help", "-h"}) {
                CommandRunner each = new CommandRunner();
                assertEquals(ExitCodes.OK, each.run(command, flag), command + " " + flag + ": " + each.err());
                assertTrue(each.out().contains("Usage: scenes " + command), command + " " + flag + ": " + each.out());
            }
        }
    }

    @Test
    void versionNamesTheReleaseAndTheCommitItWasBuiltFrom() throws IOException, InterruptedException {
        assertEquals(ExitCodes.OK, run("--version"));
        String first = cli.out().lines().findFirst().orElse("");
        assertTrue(first.matches("scenes [0-9]+\\.[0-9]+\\.[0-9]+(-SNAPSHOT)?, commit ([0-9a-f]{40}|unknown)"), first);
        // built from this clone: the commit is the clone's HEAD, wherever git can tell it
        Process git;
        try {
            git = new ProcessBuilder("git", "-C", Path.of(System.getProperty("scenes.root", ".")).toString(),
                    "rev-parse", "HEAD").redirectErrorStream(true).start();
        } catch (IOException noGit) {
            return;
        }
        String head = new String(git.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        if (git.waitFor() == 0 && head.matches("[0-9a-f]{40}")) {
            assertTrue(first.endsWith("commit " + head), first + " (HEAD " + head + ")");
        }
    }
}
