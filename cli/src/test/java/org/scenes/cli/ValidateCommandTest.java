package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
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
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/** Drives validate and tune through the real command line on small generated scene files. */
class ValidateCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    private int run(Object... args) {
        return cli.run(args);
    }

    /** A Krislet-like player: kicks near the ball, dashes when it faces it, turns otherwise. */
    private Path player(String name, long seed, int count) throws Exception {
        Random random = new Random(seed);
        Observer observer = new Observer("T", Side.LEFT, (int) seed);
        Path file = dir.resolve(name + ".json");
        try (SceneFileWriter writer = SceneFileWriter.create(file, SceneFileHeader.of(Grid.DEFAULT, new SceneSource(name, observer)))) {
            for (int i = 0; i < count; i++) {
                double distance = random.nextInt(8) == 0 ? 0.5 : 2 + random.nextInt(30);
                double direction = random.nextInt(3) == 0 ? 0 : random.nextInt(61) - 30;
                double goal = random.nextInt(41) - 20;
                Action action = distance <= 1 ? Action.kick(100, goal) : direction == 0 ? Action.dash(10 * distance) : Action.turn(direction);
                writer.write(new Scene(i, observer, List.of(
                        SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT),
                        SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 30, goal, Grid.DEFAULT)), List.of(action)));
            }
            writer.commit();
        }
        return file;
    }

    private JsonNode json() throws Exception {
        return ConfigFiles.JSON.readTree(cli.out());
    }

    @Test
    void selfValidationIsPerfectAndJsonHasTheDocumentedKeys() throws Exception {
        Path train = player("a", 1, 300);
        assertEquals(0, run("validate", "--train", train, "--self", "--metric", "ball-goal", "--json"), cli.err());
        JsonNode result = json();
        assertEquals(1.0, result.get("accuracy").asDouble());
        for (String key : List.of("macroF1", "perAction", "confusion", "scenesPer100ms")) {
            assertTrue(result.has(key), key);
        }
        assertEquals(result.get("kick").get("total").asInt(), result.get("kick").get("correct").asInt());
        assertTrue(result.get("kick").get("total").asInt() > 10);
        assertTrue(result.get("decisionMicros").has("p99"));
        JsonNode time = result.get("decisionMicros");
        assertTrue(time.get("p50").asDouble() <= time.get("p99").asDouble(), time.toString());
    }

    @Test
    void decisionTimeLinePrintsTheMedianAndFlagsWarmUpOutliers() {
        Action[] actions = new Action[100];
        java.util.Arrays.fill(actions, Action.dash(50));
        long[] steady = new long[100];
        java.util.Arrays.fill(steady, 20_000);
        long[] warmUp = steady.clone();
        warmUp[0] = 50_000_000;
        java.io.StringWriter text = new java.io.StringWriter();
        ReportTables.printRun(new java.io.PrintWriter(text, true),
                org.scenes.internal.validate.ValidationReport.of(10, actions, actions, steady));
        assertTrue(text.toString().contains("mean 20.0 us, p50 20.0 us, p99 20.0 us, max 20.0 us"), text.toString());
        assertFalse(text.toString().contains("warm-up"), text.toString());
        text = new java.io.StringWriter();
        ReportTables.printRun(new java.io.PrintWriter(text, true),
                org.scenes.internal.validate.ValidationReport.of(10, actions, actions, warmUp));
        assertTrue(text.toString().contains("mean 519.8 us (warm-up included), p50 20.0 us, p99 20.0 us, max 50000.0 us"),
                text.toString());
        assertTrue(text.toString().contains("the max is JIT warm-up or a GC pause"), text.toString());
    }

    @Test
    void trainTestTablesSeveralMetricsAndAChart() throws Exception {
        Path a = player("a", 1, 300);
        Path b = player("b", 2, 200);
        Path chart = dir.resolve("chart.png");
        assertEquals(0, run("validate", "--train", a, "--test", b, "--metric", "random,ball-goal",
                "--chart", chart), cli.err());
        String table = cli.out();
        assertTrue(table.contains("Action accuracy"), table);
        assertTrue(table.contains("Confusion"), table);
        assertTrue(table.contains("Scenes                   train 300, test 200"), table);
        assertTrue(Files.size(chart) > 1000);
        byte[] head = Files.readAllBytes(chart);
        assertEquals((byte) 0x89, head[0]);
        assertEquals('P', head[1]);
        Path svg = dir.resolve("chart.svg");
        assertEquals(0, run("validate", "--train", a, "--test", b, "--metric", "ball-goal", "--chart", svg, "--json"));
        assertTrue(Files.readString(svg).contains("<svg"));
    }

    @Test
    void predictionsListEveryTestSceneAsTheReportCountsThem() throws Exception {
        Path a = player("a", 1, 300);
        Path b = player("b", 2, 200);
        Path csv = dir.resolve("predictions.csv");
        assertEquals(0, run("validate", "--train", a, "--test", b, "--metric", "random,ball-goal", "--predictions", csv,
                "--json"), cli.err());
        JsonNode runs = json().get("configurations");
        assertFalse(cli.out().contains("Predictions written"), "--json prints JSON only");
        List<org.apache.commons.csv.CSVRecord> rows;
        try (java.io.Reader in = Files.newBufferedReader(csv);
             org.apache.commons.csv.CSVParser parser = org.apache.commons.csv.CSVParser.parse(in,
                     org.apache.commons.csv.CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).build())) {
            assertEquals(List.of("configuration", "file", "cycle", "recorded", "predicted", "type_right", "direction_right",
                    "neighbour_file", "neighbour_cycle", "neighbour_distance"), parser.getHeaderNames());
            rows = parser.getRecords();
        }
        assertEquals(400, rows.size(), "200 test scenes for each of 2 configurations");
        for (int run = 0; run < 2; run++) {
            List<org.apache.commons.csv.CSVRecord> own = rows.subList(200 * run, 200 * (run + 1));
            assertEquals(runs.get(run).get("label").asText(), own.get(0).get("configuration"));
            long right = own.stream().filter(r -> r.get("type_right").equals("true")).count();
            long withDirection = own.stream().filter(r -> r.get("direction_right").equals("true")).count();
            assertEquals(runs.get(run).get("accuracy").asDouble(), right / 200.0, 1e-12);
            assertEquals(runs.get(run).get("directionAccuracy").asDouble(), withDirection / 200.0, 1e-12);
            for (int i = 0; i < own.size(); i++) {
                assertEquals("b.json", own.get(i).get("file"));
                assertEquals(a.toString(), own.get(i).get("neighbour_file"), "the one training file, as given");
                assertTrue(Integer.parseInt(own.get(i).get("neighbour_cycle")) < 300, own.get(i).toString());
                assertTrue(Double.parseDouble(own.get(i).get("neighbour_distance")) >= 0, own.get(i).toString());
                assertEquals(Integer.toString(i), own.get(i).get("cycle"));
                String recorded = own.get(i).get("recorded");
                String predicted = own.get(i).get("predicted");
                assertEquals(recorded.substring(0, 3).equals(predicted.substring(0, 3)), own.get(i).get("type_right").equals("true"),
                        recorded + " against " + predicted);
            }
        }
        Path again = dir.resolve("again.csv");
        assertEquals(0, run("validate", "--train", a, "--test", b, "--metric", "ball-goal", "--predictions", again),
                cli.err());
        assertTrue(cli.out().contains("Predictions written      " + again), cli.out());
        assertEquals(ExitCodes.USAGE, run("validate", "--folds", a, b, "--predictions", csv));
        assertTrue(cli.err().contains("--predictions"), cli.err());
        assertEquals(ExitCodes.USAGE, run("validate", "--train", a, "--test", b, "--predictions", dir.resolve("p.txt")));
        assertTrue(cli.err().contains("--predictions"), cli.err());
    }

    @Test
    void sideWeightTellsDeadAheadFromOneDegreeOff() throws Exception {
        // the player dashes only when the ball is at exactly 0 degrees: degrees alone cannot say that
        Path a = player("a", 1, 600);
        Path b = player("b", 2, 400);
        List<Object> polar = List.of("validate", "--train", a, "--test", b, "--metric", "continuous", "--object-weights",
                "ball=1", "--option", "space=polar", "--option", "distance-weight=3", "--json");
        assertEquals(0, run(polar.toArray()), cli.err());
        double plain = json().get("accuracy").asDouble();
        List<Object> sided = new ArrayList<>(polar);
        sided.addAll(List.of("--option", "side-weight=100"));
        assertEquals(0, run(sided.toArray()), cli.err());
        double withSide = json().get("accuracy").asDouble();
        assertTrue(plain < 0.97, "without sides: " + plain);
        assertTrue(withSide > plain + 0.02 && withSide > 0.98, "with sides: " + withSide + ", without: " + plain);
    }

    @Test
    void foldsTuneAndConfigWorkTogether() throws Exception {
        List<Path> files = new ArrayList<>();
        for (int i = 1; i <= 3; i++) {
            files.add(player("p" + i, i, 150));
        }
        List<Object> args = new ArrayList<>(List.of("validate", "--folds"));
        args.addAll(files);
        args.addAll(List.of("--metric", "ball-goal", "--json"));
        assertEquals(0, run(args.toArray()), cli.err());
        JsonNode folds = json();
        assertEquals(3, folds.get("folds").asInt());
        assertTrue(folds.get("accuracy").asDouble() > 0.5);

        Path config = dir.resolve("best.json");
        List<Object> tune = new ArrayList<>(List.of("tune", "--quiet", "-o", config, "--sweeps", "1", "--train"));
        tune.addAll(files);
        assertEquals(0, run(tune.toArray()), cli.err());
        JsonNode written = ConfigFiles.JSON.readTree(config.toFile());
        assertTrue(written.has("metric") && written.has("crossValidation") && written.has("objectWeights"));

        assertEquals(0, run("validate", "--config", config, "--train", files.get(0), "--test", files.get(1), "--json"), cli.err());
        assertEquals(written.get("metric").asText(), json().get("config").get("metric").asText());
    }

    @Test
    @RequiresSharedData
    void realKrisletLogsAreImitatedFarAboveChance() throws Exception {
        Path data = SharedData.resolve("krislet");
        Path train = dir.resolve("train.json.gz");
        Path test = dir.resolve("test.json.gz");
        assertEquals(0, run("convert", data.resolve("classic-game1/Carleton_1.lsf.gz"), "-o", train), cli.err());
        assertEquals(0, run("convert", data.resolve("classic-game2/Carleton_1.lsf.gz"), "-o", test), cli.err());
        assertEquals(0, run("validate", "--train", train, "--self", "--metric", "continuous", "--json"), cli.err());
        assertEquals(1.0, json().get("accuracy").asDouble(), "each scene finds itself");
        assertEquals(0, run("validate", "--train", train, "--test", test, "--metric", "random,ball-goal", "--json"), cli.err());
        JsonNode runs = json().get("configurations");
        double random = runs.get(0).get("accuracy").asDouble();
        double ballGoal = runs.get(1).get("accuracy").asDouble();
        assertTrue(random < 0.75, "random: " + random);
        assertTrue(ballGoal > 0.95, "ball-goal: " + ballGoal);
    }

    @Test
    void badUsageIsReportedClearly() throws Exception {
        Path a = player("a", 1, 20);
        assertEquals(ExitCodes.USAGE, run("validate", "--train", a));
        assertTrue(cli.err().contains("--test"), cli.err());
        assertEquals(ExitCodes.USAGE, run("validate", "--train", a, "--self", "--metric", "nonesuch"));
        assertTrue(cli.err().contains("Available metrics"), cli.err());
        assertEquals(ExitCodes.USAGE, run("validate", "--train", a, "--self", "--metric", "ball-goal", "--option", "speed=3"));
        assertTrue(cli.err().contains("no option 'speed'"), cli.err());
        assertFalse(Files.exists(dir.resolve("x.png")));
    }
}
