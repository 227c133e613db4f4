package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/** {@code scenes bench} on converted Krislet scenes prints one positive rate per metric. */
class BenchCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    private int run(Object... args) {
        return cli.run(args);
    }

    @Test
    @RequiresSharedData
    void tableHasARatePerMetric() {
        Path log = SharedData.resolve("krislet/classic-game1/Carleton_1.lsf.gz");
        Path scenes = dir.resolve("c1.json.gz");
        assertEquals(0, run("convert", "-o", scenes.toString(), log.toString()), cli.err());
        assertEquals(0, run("bench", "--time", "0.05", "--metric", "ball-goal", "--metric", "continuous", scenes.toString()), cli.err());
        List<String> rows = new ArrayList<>();
        for (String line : cli.out().split("\n")) {
            if (line.startsWith("ball-goal") || line.startsWith("continuous")) {
                rows.add(line);
                long rate = Long.parseLong(line.substring(line.lastIndexOf(' ') + 1).replace(",", ""));
                assertTrue(rate > 0, line);
            }
        }
        assertEquals(2, rows.size(), cli.out());
    }

    @Test
    @RequiresSharedData
    void heldOutQueriesAreEverySceneOfTheirFiles() {
        Path game = SharedData.resolve("krislet/classic-game1");
        Path stored = dir.resolve("c1.json.gz");
        Path held = dir.resolve("c2.json.gz");
        assertEquals(0, run("convert", "-o", stored.toString(), game.resolve("Carleton_1.lsf.gz").toString()), cli.err());
        assertEquals(0, run("convert", "-o", held.toString(), game.resolve("Carleton_2.lsf.gz").toString()), cli.err());
        int count = org.scenes.internal.scene.SceneFileReader.read(held).scenes().size();
        assertEquals(0, run("bench", "--time", "0.02", "--metric", "ball-goal", "--queries", held, stored), cli.err());
        assertTrue(cli.out().split("\n")[0].contains(", " + count + " queries,"), cli.out());
        assertEquals(2, run("bench", "--synthetic", 100, "--queries", held), cli.out());
    }

    @Test
    void queryCountSetsHowManyQueries() {
        assertEquals(0, run("bench", "--time", "0.02", "--metric", "ball-goal", "--synthetic", 500, "--query-count", 10), cli.err());
        assertTrue(cli.out().split("\n")[0].startsWith("500 stored synthetic scenes"), cli.out());
        assertTrue(cli.out().split("\n")[0].contains(", 10 queries,"), cli.out());
        assertEquals(2, run("bench", "--synthetic", 500, "--query-count", 0));
    }

    @Test
    void syntheticRunsAreSaidAndNeedSyntheticScenes() {
        assertEquals(0, run("bench", "--time", "0.02", "--metric", "ball-goal", "--synthetic", 400, "--synthetic-run", 4,
                "--query-count", 8), cli.err());
        assertTrue(cli.out().split("\n")[0].contains("runs of 4 cycles"), cli.out());
        assertEquals(2, run("bench", "--synthetic", 400, "--synthetic-run", 0));
        assertTrue(cli.err().contains("--synthetic-run"), cli.err());
        assertEquals(2, run("bench", "--synthetic-run", 3, "x.json"));
        assertTrue(cli.err().contains("--synthetic-run"), cli.err());
    }

    @Test
    void syntheticKnowledgeBaseOfTheGivenSize() {
        assertEquals(0, run("bench", "--time", "0.05", "--metric", "ball-goal", "--synthetic", 3000), cli.err());
        String[] lines = cli.out().split("\n");
        assertTrue(lines[0].startsWith("3000 stored synthetic scenes"), cli.out());
        String row = lines[2];
        assertTrue(row.startsWith("ball-goal"), cli.out());
        assertTrue(Long.parseLong(row.substring(row.lastIndexOf(' ') + 1).replace(",", "")) > 0, row);
    }

    @Test
    void byDefaultEveryBuiltInMetricWithBallGoalIndexAndScanApart() {
        assertEquals(0, run("bench", "--time", "0.02", "--synthetic", 2000), cli.err());
        List<String> labels = new ArrayList<>();
        for (String line : cli.out().split("\n")) {
            if (line.matches(".*\\s[0-9,]+$")) {
                labels.add(line.substring(0, 24).trim());
            }
        }
        assertEquals(List.of("ball-goal (index)", "ball-goal (scan)", "continuous", "cell", "projection", "continuous (optimal)"),
                labels, cli.out());
        assertTrue(cli.out().contains("over decision time"), cli.out());
    }

    @Test
    void latencyColumnsAndAConfigurationFromTune() throws Exception {
        Path config = dir.resolve("tuned.json");
        java.nio.file.Files.writeString(config, "{\"metric\": \"continuous\", \"options\": {\"space\": \"polar\","
                + " \"memory-action\": \"100\"}, \"objectWeights\": \"ball=1,goal=0.05\", \"transforms\": [\"memory\"]}");
        assertEquals(0, run("bench", "--time", "0.02", "--synthetic", 1500, "--metric", "ball-goal", "--config", config,
                "--latency"), cli.err());
        List<String> rows = new ArrayList<>();
        for (String line : cli.out().split("\n")) {
            if (line.matches("\\S+\\s+[0-9,]+\\s+[0-9.]+ / [0-9.]+\\s+[0-9.]+ / [0-9.]+")) {
                rows.add(line.substring(0, 24).trim());
                String[] parts = line.trim().split("\\s+");
                assertTrue(Double.parseDouble(parts[2]) <= Double.parseDouble(parts[4]), "p50 <= p99: " + line);
            }
        }
        assertEquals(List.of("ball-goal", "tuned.json"), rows, cli.out());
    }

    @Test
    void knowledgeBaseFromFilesOrSyntheticExactlyOne() {
        assertEquals(ExitCodes.USAGE, run("bench", "--time", "0.05"));
        assertTrue(cli.err().contains("--synthetic"), cli.err());
        assertEquals(ExitCodes.USAGE, run("bench", "--synthetic", 100, "x.json"));
        assertEquals(ExitCodes.USAGE, run("bench", "--synthetic", 0));
    }

    @Test
    void nonPositiveTimeIsAUsageError() {
        assertEquals(ExitCodes.USAGE, run("bench", "--time", "0", "x.json"));
    }
}
