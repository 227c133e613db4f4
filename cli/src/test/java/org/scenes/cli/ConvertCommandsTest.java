package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/**
 * Drives convert, show, stats and export through the real command line on recorded logs;
 * {@link SimulatedGameCommandsTest} drives them on a simulated game.
 */
class ConvertCommandsTest {
    private static final Path DATA = SharedData.data();
    private static final Path CARLETON_1 = DATA.resolve("krislet/classic-game1/Carleton_1.lsf.gz");

    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    private int run(Object... args) {
        return cli.run(args);
    }

    @Test
    @RequiresSharedData
    void convertWritesTheScenesAndPrintsASummary() {
        Path target = dir.resolve("c1.json.gz");
        assertEquals(0, run("convert", CARLETON_1, "-o", target), cli.err());
        SceneFile file = SceneFileReader.read(target);
        // the number SharedLogsTest derives with awk for this log
        assertEquals(2592, file.scenes().size());
        assertEquals("Carleton", file.header().source().observer().team());
        assertEquals(Grid.DEFAULT, file.grid());
        String summary = cli.out();
        assertTrue(summary.contains("Scenes written         2592"), summary);
        assertTrue(summary.contains("no action            859"), summary);
        assertTrue(summary.contains("Malformed lines        0"), summary);
    }

    @Test
    @RequiresSharedData
    void convertHonoursTheGridOptions() {
        Path target = dir.resolve("g.json");
        assertEquals(0, run("convert", CARLETON_1, "-o", target, "--grid", "3x4", "--bounds", "1,5,20"), cli.err());
        assertEquals(Grid.of(3, 1, 5, 20), SceneFileReader.read(target).grid());
        assertEquals(2, run("convert", CARLETON_1, "-o", target, "--grid", "3x4"));
        assertTrue(cli.err().contains("give --bounds with 3 distances"), cli.err());
    }

    @Test
    @RequiresSharedData
    void outDirWritesOneFilePerLog() {
        Path second = DATA.resolve("krislet/classic-game1/University_1.lsf.gz");
        assertEquals(0, run("convert", CARLETON_1, second, "--out-dir", dir.resolve("out")), cli.err());
        assertTrue(Files.exists(dir.resolve("out/Carleton_1.json.gz")));
        assertEquals("University", SceneFileReader.read(dir.resolve("out/University_1.json.gz"))
                .header().source().observer().team());
    }

    @Test
    @RequiresSharedData
    void outDirKeepsLogsOfTheSameNameApart() {
        Path other = DATA.resolve("krislet/classic-game2/Carleton_1.lsf.gz");
        assertEquals(0, run("convert", CARLETON_1, other, "--out-dir", dir), cli.err());
        assertEquals(2592, SceneFileReader.read(dir.resolve("classic-game1-Carleton_1.json.gz")).scenes().size());
        assertTrue(Files.exists(dir.resolve("classic-game2-Carleton_1.json.gz")));
        assertEquals(2, run("convert", CARLETON_1, CARLETON_1, "--out-dir", dir));
        assertTrue(cli.err().contains("two logs would both be written"), cli.err());
    }

    @Test
    void malformedLinesWarnWithFileAndLineAndStrictStopsWithoutOutput() throws IOException {
        Path log = dir.resolve("bad.lsf");
        Files.write(log, List.of("(init A (version 9))", "(init l 1 before_kick_off)", "(see 0 ((b) 1 2)",
                "(see 1 ((b) 1 2))", "(dash 5)"));
        Path target = dir.resolve("bad.json");
        assertEquals(0, run("convert", log, "-o", target));
        assertTrue(cli.err().contains("warning: " + log + ":3: column"), cli.err());
        assertTrue(cli.out().contains("Malformed lines        1"), cli.out());
        assertEquals(1, SceneFileReader.read(target).scenes().size());

        Path strictTarget = dir.resolve("strict.json");
        assertEquals(1, run("convert", log, "--strict", "-o", strictTarget));
        assertTrue(cli.err().contains("scenes: " + log + ":3: column"), cli.err());
        assertFalse(Files.exists(strictTarget), "nothing is half-written");
    }

    @Test
    @RequiresSharedData
    void convertNeedsExactlyOneOutput() {
        assertEquals(2, run("convert", CARLETON_1));
        assertEquals(2, run("convert", CARLETON_1, "-o", dir.resolve("a.json"), "--out-dir", dir));
    }

    @Test
    @RequiresSharedData
    void showStatsAndExport() throws IOException {
        Path scenes = dir.resolve("c1.json");
        assertEquals(0, run("convert", CARLETON_1, "-o", scenes));

        assertEquals(0, run("show", scenes, "--index", "3"));
        assertTrue(cli.out().startsWith("#3  Scene cycle 0  Carleton 1 (l)"), cli.out());
        assertTrue(cli.out().contains("action: dash power=603"), cli.out());
        assertEquals(2, run("show", scenes, "--cycle", "99999"));
        assertTrue(cli.err().contains("no scene with cycle 99999"), cli.err());

        assertEquals(0, run("stats", scenes));
        // zcat Carleton_1.lsf.gz | grep -c '^(kick ' = 10; every kick follows a see of its own
        assertTrue(cli.out().matches("(?s).*\\n  kick +10 .*"), cli.out());
        assertTrue(cli.out().contains("Scenes                   2592"), cli.out());

        assertEquals(0, run("export", "--format", "csv", scenes));
        List<String> csv = cli.out().lines().toList();
        assertEquals(2593, csv.size(), "a header and one row per scene");
        assertTrue(csv.get(0).startsWith("cycle,ball_dist,ball_dir,own_goal_dist"));
        assertTrue(csv.get(0).endsWith(",unknown_players,action"));
        assertEquals(csv.get(0).split(",").length, csv.get(1).split(",", -1).length);
        assertEquals(10, csv.stream().filter(l -> l.endsWith(",kick")).count());

        Path arff = dir.resolve("c1.arff");
        assertEquals(0, run("export", "--format", "arff", scenes, "-o", arff, "--players", "1"));
        List<String> lines = Files.readAllLines(arff);
        int data = lines.indexOf("@data");
        assertEquals(2592, lines.size() - data - 1);
        assertTrue(lines.contains("@attribute action {dash,kick,turn_neck,turn,catch,move,tackle}"));
        assertTrue(lines.get(data + 1).contains(",?,"), "missing values are '?' in ARFF");
        assertEquals(13, lines.get(data + 1).split(",").length);
    }
}
