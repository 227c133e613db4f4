package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * {@code scenes experiment}: result files, and the proof that a configuration gives the same
 * numbers inside a parallel sweep as {@code scenes validate --folds} gives for it alone.
 */
class ExperimentCommandTest {
    private static final int SCENES_PER_FILE = 400;

    @TempDir
    static Path work;
    static List<Path> folds = new ArrayList<>();

    /**
     * Three small scene files (the first scenes of three Krislet players of a seeded simulated
     * game: nothing here depends on recorded data), one fold each.
     */
    @BeforeAll
    static void sceneFiles() throws IOException {
        Path game = Files.createDirectories(work.resolve("game"));
        new Simulator(new GameSetup(new GameSetup.Team("Carleton", 3, Teachers.byName("krislet")),
                new GameSetup.Team("University", 3, Teachers.byName("krislet")), 1500, 1, game)).run(t -> { });
        for (int player = 1; player <= 3; player++) {
            List<Scene> scenes = new ArrayList<>();
            SceneConverter.with(Grid.DEFAULT).build().convert(game.resolve("Carleton_" + player + ".lsf.gz"), scenes::add);
            Path file = work.resolve("Carleton_" + player + ".json");
            SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT, new SceneSource("Carleton_" + player, null)),
                    scenes.subList(0, SCENES_PER_FILE)));
            folds.add(file);
        }
    }

    private final CommandRunner cli = new CommandRunner();

    private int run(Object... args) {
        return cli.run(args);
    }

    private static String quoted(Path path) {
        return "'" + path.toString().replace("\\", "/") + "'";
    }

    @Test
    void eachConfigurationGivesTheNumbersOfValidateAlone() throws IOException {
        // random metric and vote-random selector: numbers that depend on the seed and the query order
        Path sweep = Files.writeString(work.resolve("random.groovy"), """
                title 'Random metric and selector'
                data %s, %s, %s
                metrics 'random', 'ball-goal'
                k 1, 5
                selectors 'vote-random', 'random'
                seed 7
                table columns: 'k'
                """.formatted(quoted(folds.get(0)), quoted(folds.get(1)), quoted(folds.get(2))));
        Path results = work.resolve("results");
        assertEquals(ExitCodes.OK, run("experiment", sweep.toString(), "--out-dir", results.toString(), "--threads", "4"),
                cli.err());
        List<String> csv = Files.readAllLines(results.resolve("random.csv"));
        assertEquals(1 + 8, csv.size());
        assertEquals("metric,weights,k,selector,action-weights,accuracy,accuracyStd,directionAccuracy,macroF1,kickRecall,"
                + "turnSignAgreement", csv.get(0));
        ObjectMapper json = new ObjectMapper();
        for (String row : csv.subList(1, csv.size())) {
            String[] cells = row.split(",");
            StringWriter alone = new StringWriter();
            int status = Main.run(new PrintWriter(alone), new PrintWriter(new StringWriter()), "validate", "--folds",
                    folds.get(0).toString(), folds.get(1).toString(), folds.get(2).toString(), "--metric", cells[0],
                    "--object-weights", cells[1], "--k", cells[2], "--selector", cells[3], "--action-weights", cells[4],
                    "--seed", "7", "--json");
            assertEquals(ExitCodes.OK, status);
            JsonNode report = json.readTree(alone.toString());
            assertEquals(report.get("accuracy").asDouble(), Double.parseDouble(cells[5]), 0, row);
            assertEquals(report.get("macroF1").asDouble(), Double.parseDouble(cells[8]), 0, row);
        }
        assertTrue(Files.readString(results.resolve("random.json")).contains("\"command\" : \"scenes experiment "
                + sweep + " --out-dir " + results + "\""));
        assertTrue(Files.readString(results.resolve("random.md")).contains("| metric / selector \\ k | 1 | 5 |"));
        assertTrue(Files.readString(results.resolve("random.svg")).startsWith("<?xml"));
        assertTrue(cli.out().contains("| random / vote-random |"), cli.out());
    }

    @Test
    void sweepErrorsAreUsageErrorsNamingTheScriptLine() throws IOException {
        Path sweep = Files.writeString(work.resolve("bad.groovy"), """
                data %s, %s
                metrics 'ball-goal'
                k 0
                selectors 'vote'
                """.formatted(quoted(folds.get(0)), quoted(folds.get(1))));
        assertEquals(ExitCodes.USAGE, run("experiment", sweep.toString()));
        assertTrue(cli.err().contains("k must be at least 1, not 0"), cli.err());
        Path unknown = Files.writeString(work.resolve("unknown.groovy"), """
                data %s, %s
                metrics 'no-such-metric'
                selectors 'vote'
                """.formatted(quoted(folds.get(0)), quoted(folds.get(1))));
        assertEquals(ExitCodes.USAGE, run("experiment", unknown.toString()));
        assertTrue(cli.err().contains("no metric named 'no-such-metric'"), cli.err());
        Path typo = Files.writeString(work.resolve("typo.groovy"), "selector 'vote'\n");
        assertEquals(ExitCodes.USAGE, run("experiment", typo.toString()));
        assertTrue(cli.err().contains(typo + ":1:1: [Static type checking]"), cli.err());
    }

    @Test
    void missingSceneFileSaysHowToMakeIt() throws IOException {
        Path sweep = Files.writeString(work.resolve("missing.groovy"), """
                data 'nowhere/a.json.gz', 'nowhere/b.json.gz'
                metrics 'ball-goal'
                selectors 'vote'
                """);
        assertEquals(ExitCodes.USAGE, run("experiment", sweep.toString()));
        assertTrue(cli.err().contains("the sweep's scene file nowhere/a.json.gz does not exist"), cli.err());
        assertTrue(cli.err().contains("scenes convert"), cli.err());
    }
}
