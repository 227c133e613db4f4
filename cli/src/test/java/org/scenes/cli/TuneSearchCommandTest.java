package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

/** {@code scenes tune --search random}, its budget and table, and {@code scenes export} of several files. */
class TuneSearchCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    /**
     * A player that kicks near the ball, dashes facing it and otherwise turns the way it turned
     * before when the ball is out of sight (so memory of the previous action pays); flags and a
     * teammate are seen too, so the wide search has more than ball and goal to weigh.
     */
    private Path player(String name, long seed, int count) throws Exception {
        Random random = new Random(seed);
        Observer observer = new Observer("T", Side.LEFT, (int) seed);
        Path file = dir.resolve(name + ".json");
        try (SceneFileWriter writer = SceneFileWriter.create(file, SceneFileHeader.of(Grid.DEFAULT, new SceneSource(name, observer)))) {
            double lastTurn = 30;
            for (int i = 0; i < count; i++) {
                List<SeenObject> objects = new ArrayList<>();
                boolean seen = random.nextInt(5) > 0;
                double distance = random.nextInt(8) == 0 ? 0.5 : 2 + random.nextInt(30);
                double direction = random.nextInt(3) == 0 ? 0 : random.nextInt(61) - 30;
                double goal = random.nextInt(41) - 20;
                if (seen) {
                    objects.add(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT));
                }
                objects.add(SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 30, goal, Grid.DEFAULT));
                objects.add(SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, 10 + random.nextInt(40), random.nextInt(91) - 45, Grid.DEFAULT));
                objects.add(SeenObject.simple(ObjectKind.PLAYER, "p \"T\" 2", Relation.TEAMMATE, 5 + random.nextInt(20),
                        random.nextInt(91) - 45, Grid.DEFAULT));
                Action action;
                if (!seen) {
                    action = Action.turn(lastTurn);
                } else if (distance <= 1) {
                    action = Action.kick(100, goal);
                } else if (direction == 0) {
                    action = Action.dash(10 * distance);
                } else {
                    action = Action.turn(direction);
                    lastTurn = direction > 0 ? 30 : -30;
                }
                writer.write(new Scene(i, observer, objects, List.of(action)));
            }
            writer.commit();
        }
        return file;
    }

    private List<Path> players(int count, int scenes) throws Exception {
        List<Path> files = new ArrayList<>();
        for (int i = 1; i <= count; i++) {
            files.add(player("p" + i, i, scenes));
        }
        return files;
    }

    private static List<CSVRecord> csv(Path file) throws Exception {
        try (Reader in = Files.newBufferedReader(file);
             CSVParser parser = CSVParser.parse(in, CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).build())) {
            return parser.getRecords();
        }
    }

    private List<Object> tune(List<Path> files, Object... more) {
        List<Object> args = new ArrayList<>(List.of("tune", "--train"));
        args.addAll(files);
        args.addAll(List.of(more));
        return args;
    }

    @Test
    void randomSearchTriesTheBudgetNarrowsByRungsAndRepeatsItself() throws Exception {
        List<Path> files = players(3, 240);
        Path config = dir.resolve("best.json");
        Path table = dir.resolve("tried.csv");
        assertEquals(0, cli.run(tune(files, "--search", "random", "--budget", "30", "--seed", "5", "--table", table,
                "-o", config).toArray()), cli.err());
        JsonNode written = ConfigFiles.JSON.readTree(config.toFile());
        JsonNode cv = written.get("crossValidation");
        assertEquals(30, cv.get("configurationsTried").asInt());
        List<CSVRecord> rows = csv(table);
        assertEquals(rows.size(), cv.get("scores").asInt());
        assertEquals(TriedTable.COLUMNS.size(), rows.get(0).size());
        Set<String> rungs = new HashSet<>();
        int firstRung = 0;
        for (CSVRecord row : rows) {
            rungs.add(row.get("rung"));
            if (row.get("rung").equals("0")) {
                firstRung++;
            }
        }
        assertEquals(30, firstRung, "every configuration is scored at the first rung");
        assertTrue(rungs.size() >= 3, "rungs " + rungs);
        // files of 240 scenes leave no query sample to take: the first rung scores two of the three folds, the last all
        assertEquals("480", rows.get(0).get("queries"));
        assertEquals("720", rows.get(rows.size() - 1).get("queries"));
        // more than ball and goal were tried, and memory, and several selectors
        assertTrue(rows.stream().anyMatch(r -> !r.get("objectWeights").matches("1/[^/]*/0/0/0/0/0/0")), "wider weights");
        assertTrue(rows.stream().anyMatch(r -> r.get("transforms").equals("memory")));
        assertTrue(rows.stream().anyMatch(r -> r.get("transforms").equals("long-memory") && r.get("options").contains("memory-depth")),
                "deeper memory of actions");
        assertTrue(rows.stream().map(r -> r.get("selector") + r.get("k")).distinct().count() >= 3);
        // the winner scores at least as well as every configuration of the last rung
        int last = rungs.stream().mapToInt(Integer::parseInt).max().orElseThrow();
        double best = rows.stream().filter(r -> r.get("rung").equals(Integer.toString(last)))
                .mapToDouble(r -> Double.parseDouble(r.get("score"))).max().orElseThrow();
        assertEquals(best, cv.get("score").asDouble(), 1e-9);
        // the same seed gives the same table, whatever the threads did
        Path again = dir.resolve("again.csv");
        assertEquals(0, cli.run(tune(files, "--search", "random", "--budget", "30", "--seed", "5", "--table", again,
                "-o", dir.resolve("again.json")).toArray()), cli.err());
        assertEquals(Files.readString(table), Files.readString(again));
    }

    @Test
    void descentWritesItsTableAsJson() throws Exception {
        List<Path> files = players(3, 120);
        Path table = dir.resolve("tried.json");
        assertEquals(0, cli.run(tune(files, "--quiet", "--sweeps", "1", "--table", table, "-o", dir.resolve("c.json")).toArray()),
                cli.err());
        JsonNode rows = ConfigFiles.JSON.readTree(table.toFile());
        JsonNode written = ConfigFiles.JSON.readTree(dir.resolve("c.json").toFile());
        assertEquals(written.get("crossValidation").get("configurationsTried").asInt(), rows.size());
        assertTrue(rows.get(0).has("macroF1") && rows.get(0).has("describe"));
    }

    @Test
    void badBudgetsAndTablesAreUsageErrors() throws Exception {
        List<Path> files = players(2, 50);
        Path out = dir.resolve("c.json");
        for (String budget : List.of("0", "5x", "-3")) {
            assertEquals(2, cli.run(tune(files, "--search", "random", "--budget", budget, "-o", out).toArray()), budget);
            assertTrue(cli.err().contains("--budget"), cli.err());
        }
        assertEquals(2, cli.run(tune(files, "--budget", "20", "-o", out).toArray()));
        assertTrue(cli.err().contains("--search random"), cli.err());
        assertEquals(2, cli.run(tune(files, "--search", "random", "--table", dir.resolve("t.txt"), "-o", out).toArray()));
        assertTrue(cli.err().contains("--table"), cli.err());
        assertEquals(2, cli.run(tune(files, "--search", "grid", "-o", out).toArray()));
        assertEquals(2, cli.run(tune(files, "--metrics", "cell", "-o", out).toArray()));
        assertTrue(cli.err().contains("--metrics applies to --search random"), cli.err());
        assertEquals(2, cli.run(tune(files, "--search", "random", "--metrics", "cell,nearest", "-o", out).toArray()));
        assertTrue(cli.err().contains("no metric named 'nearest'") && cli.err().contains("ball-goal"), cli.err());
        assertTrue(Files.notExists(out));
    }

    @Test
    void aRandomSearchOfNamedMetricsTriesOnlyThem() throws Exception {
        List<Path> files = players(2, 50);
        Path table = dir.resolve("tried.csv");
        Path out = dir.resolve("c.json");
        assertEquals(0, cli.run(tune(files, "--search", "random", "--metrics", "cell", "--budget", "12", "--quiet",
                "--table", table, "-o", out).toArray()), cli.err());
        List<CSVRecord> rows = csv(table);
        assertTrue(!rows.isEmpty());
        for (CSVRecord row : rows) {
            assertEquals("cell", row.get("metric"), row.toString());
        }
        assertEquals("cell", ConfigFiles.JSON.readTree(out.toFile()).get("metric").asText());
    }

    @Test
    void exportOfSeveralFilesWithParametersAndPreviousAction() throws Exception {
        List<Path> files = players(2, 40);
        Path table = dir.resolve("all.csv");
        assertEquals(0, cli.run("export", "--format", "csv", files.get(0), files.get(1), "--parameters", "--previous",
                "--players", "1", "-o", table), cli.err());
        List<CSVRecord> rows = csv(table);
        assertEquals(80, rows.size());
        assertEquals("p1.json", rows.get(0).get("file"));
        assertEquals("p2.json", rows.get(40).get("file"));
        // each file starts its own sequence: no previous action at its first scene
        assertEquals("none", rows.get(0).get("previous_action"));
        assertEquals("none", rows.get(40).get("previous_action"));
        for (int i = 1; i < 80; i++) {
            if (i == 40) {
                continue;
            }
            CSVRecord row = rows.get(i);
            CSVRecord before = rows.get(i - 1);
            assertEquals(before.get("action"), row.get("previous_action"), "row " + i);
            assertEquals(before.get("action").equals("turn") ? before.get("turn_moment") : "", row.get("previous_turn_moment"));
        }
        for (CSVRecord row : rows) {
            String action = row.get("action");
            assertEquals(action.equals("turn"), !row.get("turn_moment").isEmpty());
            assertEquals(action.equals("dash"), !row.get("dash_power").isEmpty());
            assertEquals(action.equals("kick"), !row.get("kick_power").isEmpty() && !row.get("kick_dir").isEmpty());
            if (action.equals("kick")) {
                assertEquals("100", row.get("kick_power"));
            }
        }
        assertEquals("action", rows.get(0).getParser().getHeaderNames().get(rows.get(0).size() - 1));
        Path arff = dir.resolve("all.arff");
        assertEquals(0, cli.run("export", "--format", "arff", files.get(0), files.get(1), "--previous", "-o", arff), cli.err());
        String text = Files.readString(arff);
        assertTrue(text.contains("@attribute file string"), text);
        assertTrue(text.contains("@attribute previous_action {"), text);
        assertEquals(80, text.substring(text.indexOf("@data") + 6).strip().split("\n").length);
    }
}
