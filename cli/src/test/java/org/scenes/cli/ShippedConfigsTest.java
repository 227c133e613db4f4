package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.MatchConfigFile;

/**
 * The shipped configurations (examples/configs) play on scenes that {@code scenes convert} makes
 * with its defaults: the two commands the guide gives are enough.
 */
class ShippedConfigsTest {
    private final CommandRunner cli = new CommandRunner();

    @TempDir
    Path dir;

    @Test
    void everyShippedConfigurationPlaysOnScenesOfTheConvertDefaults() throws IOException {
        Path configs = Path.of(System.getProperty("scenes.root"), "examples", "configs");
        List<Path> files;
        try (var listing = Files.list(configs)) {
            files = listing.filter(f -> f.toString().endsWith(".json")).sorted().toList();
        }
        assertEquals(List.of("helios.json", "krislet.json"), files.stream().map(f -> f.getFileName().toString()).toList());

        Path logs = dir.resolve("logs");
        Path scenes = dir.resolve("scenes");
        assertEquals(0, cli.run("simulate", "--teams", "krislet:3,krislet:3", "--cycles", "600", "--seed", "2",
                "--out-dir", logs), cli.err());
        assertEquals(0, cli.run("convert", logs.resolve("Teal_1.lsf.gz"), logs.resolve("Teal_2.lsf.gz"),
                logs.resolve("Teal_3.lsf.gz"), "--out-dir", scenes), cli.err());
        // the defaults keep the world models the field metric and target replay need
        assertTrue(text(scenes.resolve("Teal_2.json.gz")).contains("\"world\":{\"x\":"));

        for (Path file : files) {
            MatchConfig config = MatchConfigFile.read(file);
            assertEquals(0, cli.run("match", "--left", "imitator:3:" + scenes + ":" + file, "--right", "krislet:3",
                    "--cycles", "600", "--json"), file + ": " + cli.err());
            JsonNode imitators = new ObjectMapper().readTree(cli.out()).get("left");
            String spec = imitators.get("spec").asText();
            assertTrue(spec.contains(config.metric()) && spec.contains("k=" + config.k()), spec);
            assertEquals(config.replay() == org.scenes.internal.target.Replay.TARGET, spec.contains("replay=target"), spec);
            JsonNode figures = imitators.get("figures");
            // the imitators play: they answer their sees and run about
            assertTrue(figures.get("sees answered").asDouble() > 0.9, file + ": " + figures);
            assertTrue(figures.get("dash share").asDouble() > 0.2, file + ": " + figures);
        }
    }

    private static String text(Path gzip) throws IOException {
        try (InputStream in = new GZIPInputStream(Files.newInputStream(gzip))) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
