package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code convert --world} writes world blocks; {@code world-error} measures them against the game log. */
class WorldErrorCommandTest {
    private final CommandRunner cli = new CommandRunner();

    @TempDir
    Path dir;

    @Test
    void scenesWithWorldModelsAreMeasuredAndScenesWithoutAreRefused() throws IOException {
        Path logs = dir.resolve("logs");
        Path record = dir.resolve("record");
        assertEquals(0, cli.run("simulate", "--teams", "krislet:2,krislet:2", "--cycles", "300", "--seed", "4",
                "--out-dir", logs, "--record", record), cli.err());
        Path rcg;
        try (var files = Files.list(record)) {
            rcg = files.filter(f -> f.toString().endsWith(".rcg")).findFirst().orElseThrow();
        }
        assertEquals(0, cli.run("convert", logs.resolve("Teal_1.lsf.gz"), logs.resolve("Amber_2.lsf.gz"),
                "--out-dir", dir.resolve("world"), "--world"), cli.err());
        assertEquals(0, cli.run("convert", logs.resolve("Teal_1.lsf.gz"), "--no-world", "--out-dir", dir.resolve("plain")), cli.err());
        assertTrue(text(dir.resolve("world/Teal_1.json.gz")).contains("\"world\":{\"x\":"));
        assertFalse(text(dir.resolve("plain/Teal_1.json.gz")).contains("\"world\""));

        assertEquals(0, cli.run("world-error", rcg, dir.resolve("world")), cli.err());
        assertTrue(cli.out().contains("position (m)"), cli.out());

        assertEquals(1, cli.run("world-error", rcg, dir.resolve("plain")));
        assertTrue(cli.err().contains("no scene with a world model"), cli.err());
        assertEquals(2, cli.run("world-error", dir.resolve("none.rcg"), dir.resolve("world")));
        assertTrue(cli.err().contains("no game log"), cli.err());
    }

    private static String text(Path gzip) throws IOException {
        try (InputStream in = new GZIPInputStream(Files.newInputStream(gzip))) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
