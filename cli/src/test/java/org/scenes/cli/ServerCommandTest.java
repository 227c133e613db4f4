package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.gamelog.GameLogReader;

/** {@code scenes server} options, and {@code scenes simulate --record}. */
class ServerCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    @Test
    void badOptionsAreUsageErrors() {
        assertEquals(2, cli.run("server", "--cycles", "0"));
        assertTrue(cli.err().contains("--cycles"), cli.err());
        assertEquals(2, cli.run("server", "--port", "70000"));
        assertTrue(cli.err().contains("--port"), cli.err());
        assertEquals(2, cli.run("server", "--think-timeout", "0"));
        assertTrue(cli.err().contains("--think-timeout"), cli.err());
    }

    @Test
    void simulateRecordsTheServersLogs() throws IOException {
        assertEquals(0, cli.run("simulate", "--teams", "krislet:2,krislet:2", "--cycles", "200", "--seed", "2",
                "--out-dir", dir.resolve("logs"), "--record", dir.resolve("server")), cli.err());
        List<Path> written;
        try (Stream<Path> files = Files.list(dir.resolve("server"))) {
            written = files.sorted().toList();
        }
        assertEquals(2, written.size(), written.toString());
        assertTrue(written.get(0).getFileName().toString().matches("Teal_\\d+-vs-Amber_\\d+\\.rcg"), written.toString());
        assertTrue(written.get(1).getFileName().toString().endsWith(".rcl"));
        assertTrue(cli.out().contains("Server log"), cli.out());
        assertEquals(201, GameLogReader.readAll(written.get(0)).stream().filter(f -> !f.playMode().startsWith("goal"))
                .map(f -> f.time()).distinct().count(), "one show per cycle 0 to 200");
    }
}
