package org.scenes.internal.gamelog;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A game's two logs found among a command line's inputs, by content, whatever they are called. */
class GameLogsTest {
    private static final String GAME = "ULG5\n(server_param (visible_angle 90))\n";
    private static final String COMMANDS = "0,0\tRecv Teal_1: (init Teal (version 15))\n";

    @TempDir
    Path dir;

    Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    Path gzip(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(file))) {
            out.write(text.getBytes(StandardCharsets.UTF_8));
        }
        return file;
    }

    @Test
    void playersLogsAreNoGame() throws IOException {
        assertNull(GameLogs.among(List.of(write("Teal_1.lsf", "(init l 1 before_kick_off)\n"))));
    }

    @Test
    void aGameLogAloneTakesTheCommandLogBesideItPlainOrGzipped() throws IOException {
        Path game = gzip("final.rcg.gz", GAME);
        Path commands = gzip("final.rcl.gz", COMMANDS);
        assertEquals(new GameLogs(game, commands), GameLogs.among(List.of(game)));
        assertEquals("final.rcg.gz + final.rcl.gz", GameLogs.among(List.of(game)).source());
        assertEquals("final", GameLogs.baseName(game.getFileName().toString()));
    }

    @Test
    void namesDoNotMatterWhenBothAreGiven() throws IOException {
        Path game = write("a.txt", GAME);
        Path commands = write("b.txt", COMMANDS);
        assertEquals(new GameLogs(game, commands), GameLogs.among(List.of(commands, game)));
    }

    @Test
    void misuseIsOneLineNamingTheFiles() throws IOException {
        Path game = write("g.rcg", GAME);
        Path other = write("h.rcg", GAME);
        Path commands = write("c.rcl", COMMANDS);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> GameLogs.among(List.of(game, other)))
                .getMessage().contains("are both game logs"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> GameLogs.among(List.of(commands)))
                .getMessage().startsWith(commands + " is a command log"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> GameLogs.among(List.of(game)))
                .getMessage().startsWith("no command log beside " + game + " (g.rcl)"));
        Path player = write("Teal_1.lsf", "(init l 1 before_kick_off)\n");
        assertTrue(assertThrows(IllegalArgumentException.class, () -> GameLogs.among(List.of(game, commands, player)))
                .getMessage().contains("not with other logs"));
    }
}
