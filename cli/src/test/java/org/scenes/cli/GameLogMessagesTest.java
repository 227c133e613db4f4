package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.files.Inputs;

/** Issue 31.8: a game's logs damaged in the common ways are blamed on the right file, for the right reason. */
class GameLogMessagesTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();
    private String gameLog;
    private String commandLog;

    @BeforeEach
    void recordAGame() throws Exception {
        assertEquals(ExitCodes.OK, cli.run("simulate", "--seed", "3", "--cycles", "300", "--record", dir.resolve("rec"),
                "--out-dir", dir.resolve("logs")), cli.err());
        try (Stream<Path> files = Files.list(dir.resolve("rec"))) {
            for (Path file : files.toList()) {
                try (InputStream in = Inputs.open(file)) {
                    String text = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
                    if (file.toString().contains(".rcg")) {
                        gameLog = text;
                    } else {
                        commandLog = text;
                    }
                }
            }
        }
    }

    @Test
    void aCommandLogCutShortIsConvertedUpToItsEndWithAWarningNotCalledAnotherGames() throws Exception {
        Path game = Files.writeString(dir.resolve("g.rcg"), gameLog);
        Path commands = Files.writeString(dir.resolve("g.rcl"), commandLog.substring(0, commandLog.length() / 3));
        assertEquals(ExitCodes.OK, cli.run("convert", game, commands, "--out-dir", dir.resolve("scenes")), cli.err());
        assertTrue(cli.err().contains("g.rcl: the command log ends at cycle"), cli.err());
        assertFalse(cli.err().contains("another game"), cli.err());
    }

    @Test
    void aGameLogOfAnUnknownVersionIsBlamedOnTheGameLog() throws Exception {
        Path game = Files.writeString(dir.resolve("bad.rcg"), "ULG9" + gameLog.substring(4));
        Path commands = Files.writeString(dir.resolve("bad.rcl"), commandLog);
        assertEquals(ExitCodes.FAILURE, cli.run("convert", game, commands, "--out-dir", dir.resolve("scenes")));
        String err = cli.err().strip();
        assertTrue(err.contains("bad.rcg") && err.contains("ULG9"), err);
        assertFalse(err.contains("is a command log"), err);
    }
}
