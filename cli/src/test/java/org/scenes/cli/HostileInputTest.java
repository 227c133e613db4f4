package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

/**
 * The defects of issue 16, each as a regression test: bad input gets one clear line naming the
 * file, line or option, exit 2 for usage and 1 for failed work, and never a silently wrong result.
 */
class HostileInputTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    /** A Krislet-like player on the given grid: kicks near the ball, dashes when facing it, turns otherwise. */
    private Path scenes(String name, Grid grid, long seed, int count) throws Exception {
        Random random = new Random(seed);
        Observer observer = new Observer("T", Side.LEFT, 1);
        Path file = dir.resolve(name + ".json");
        try (SceneFileWriter writer = SceneFileWriter.create(file, SceneFileHeader.of(grid, new SceneSource(name, observer)))) {
            for (int i = 0; i < count; i++) {
                double distance = random.nextInt(8) == 0 ? 0.5 : 2 + random.nextInt(30);
                double direction = random.nextInt(3) == 0 ? 0 : random.nextInt(61) - 30;
                double goal = random.nextInt(41) - 20;
                Action action = distance <= 1 ? Action.kick(100, goal) : direction == 0 ? Action.dash(10 * distance) : Action.turn(direction);
                writer.write(new Scene(i, observer, List.of(
                        SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, grid),
                        SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 30, goal, grid)), List.of(action)));
            }
            writer.commit();
        }
        return file;
    }

    private Path scenes(String name, long seed, int count) throws Exception {
        return scenes(name, Grid.DEFAULT, seed, count);
    }

    private Path text(String name, String content) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, content);
        return file;
    }

    /** One line on stderr, naming what it must, and no stack trace. */
    private void oneLine(String... parts) {
        String err = cli.err().strip();
        assertFalse(err.contains("\tat "), err);
        assertFalse(err.contains("Exception"), err);
        for (String part : parts) {
            assertTrue(err.contains(part), "'" + part + "' missing in: " + err);
        }
    }

    private static final String SMALL_LOG = "(init l 1 before_kick_off)\n(see 0 ((b) 1 2) ((g r) 30 0))\n(dash 100)\n"
            + "(see 1 ((b) 1 2))\n(kick 100 0)\n";

    // ---- silently wrong results --------------------------------------------------------------

    @Test
    void aTestGridUnlikeTheTrainingGridIsAnErrorNamingBothFiles() throws Exception {
        Path train = scenes("train", Grid.DEFAULT, 1, 100);
        Path test = scenes("test", Grid.of(5, 1, 5, 10), 2, 100);
        // a fault of the data (exit 1), not of the command line
        assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", train, "--test", test, "--metric", "cell"));
        oneLine(test + ": grid 5x4", "differs from 5x3", "of " + train, "same --grid and --bounds");
        assertEquals("", cli.out());
    }

    /** A scene file whose one scene sees 100,000 objects: more than a knowledge base stores of one scene. */
    private Path tooLargeToLearn() throws Exception {
        Observer observer = new Observer("T", Side.LEFT, 1);
        List<SeenObject> crowd = new ArrayList<>();
        for (int i = 0; i < 100_000; i++) {
            crowd.add(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 1 + i % 50, i % 90, Grid.DEFAULT));
        }
        Path huge = dir.resolve("huge.json");
        try (SceneFileWriter writer = SceneFileWriter.create(huge,
                SceneFileHeader.of(Grid.DEFAULT, new SceneSource("huge", observer)))) {
            writer.write(new Scene(0, observer, crowd, List.of(Action.dash(50))));
            writer.commit();
        }
        return huge;
    }

    @Test
    void aSceneTooLargeToLearnIsFailedWorkNotAUsageError() throws Exception {
        // the data is at fault, so exit 1, not 2; the reader refuses it (issue 31.4: at most 256 objects a scene)
        Path huge = tooLargeToLearn();
        Path test = scenes("test", 2, 30);
        assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", huge, "--test", test, "--metric", "cell"));
        oneLine(huge + ":5", "a scene holds at most 256 objects");
    }

    @Test
    void matchAndEvaluateSayASceneTooLargeToLearnIsFailedWorkNamingTheFile() throws Exception {
        Path huge = tooLargeToLearn();
        assertEquals(ExitCodes.FAILURE, cli.run("match", "--left", "imitator:1:" + huge, "--right", "krislet:1",
                "--cycles", "10"));
        oneLine(huge + ":5", "a scene holds at most 256 objects");
        assertEquals("", cli.out());
        CommandRunner evaluate = new CommandRunner();
        assertEquals(ExitCodes.FAILURE, evaluate.run("evaluate", huge, "--players", "1", "--opponent", "krislet:1",
                "--cycles", "10", "--seeds", "1"));
        assertTrue(evaluate.err().strip().startsWith("scenes: " + huge + ":5:")
                && evaluate.err().contains("a scene holds at most 256 objects") && evaluate.err().strip().lines().count() == 1,
                evaluate.err());
    }

    @Test
    void matchAndEvaluateStillCallABadMatchingAUsageError() throws Exception {
        Path train = scenes("train", 1, 30);
        assertEquals(ExitCodes.USAGE, cli.run("match", "--left", "imitator:1:" + train, "--right", "krislet:1",
                "--cycles", "10", "--metric", "no-such-metric"));
        oneLine("no-such-metric");
        CommandRunner evaluate = new CommandRunner();
        assertEquals(ExitCodes.USAGE, evaluate.run("evaluate", train, "--players", "1", "--opponent", "krislet:1",
                "--cycles", "10", "--seeds", "1", "--metric", "no-such-metric"));
        assertTrue(evaluate.err().contains("no-such-metric"), evaluate.err());
    }

    @Test
    void configurationKeysThatAreUnknownOrOfTheWrongTypeAreErrorsNamingKeyAndFile() throws Exception {
        Path train = scenes("train", 1, 50);
        Path many = text("many.json", "{\"k\": \"many\"}");
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--config", many, "--train", train, "--self"));
        oneLine(many + ": key 'k' must be an integer");
        Path typo = text("typo.json", "{\"metrc\": \"cell\"}");
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--config", typo, "--train", train, "--self"));
        oneLine(typo + ": unknown key 'metrc'");
        Path number = text("number.json", "{\"metric\": 3}");
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--config", number, "--train", train, "--self"));
        oneLine(number + ": key 'metric' must be a string");
        Path truncated = text("truncated.json", "{\"metric\": \"cell\",\n  \"k\": ");
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--config", truncated, "--train", train, "--self"));
        oneLine(truncated + ":2:", "not a valid configuration (JSON)");
        assertFalse(cli.err().contains("Source:"), cli.err());
        Path missing = dir.resolve("missing.json");
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--config", missing, "--train", train, "--self"));
        oneLine(missing + ": no such configuration file");
        // what tune writes is read back
        Path tuned = dir.resolve("tuned.json");
        ConfigFiles.write(tuned, org.scenes.internal.validate.MatchConfig.DEFAULT, java.util.Map.of("crossValidation", 0.5));
        assertEquals(org.scenes.internal.validate.MatchConfig.DEFAULT, ConfigFiles.read(tuned));
    }

    @Test
    void nulBytesInALineAndLinesOfNulsAreMalformed() throws Exception {
        Path log = text("nul.lsf", "(init l 1 before_kick_off)\n\0\0\0\n(see 0 ((b) 1\0 2))\n(see 1 ((b) 1 2))\0\n(dash 10)\n");
        assertEquals(ExitCodes.OK, cli.run("convert", log, "-o", dir.resolve("nul.json")), cli.err());
        assertTrue(cli.err().contains(log + ":2: NUL byte at column 1"), cli.err());
        assertTrue(cli.err().contains(log + ":3: NUL byte at column 14"), cli.err());
        assertTrue(cli.out().contains("Malformed lines        2"), cli.out());
        // the NUL a datagram ends with (after its closing parenthesis) is no fault
        assertFalse(cli.err().contains(":4:"), cli.err());
    }

    @Test
    void anEmptyTestFileIsAnErrorAndAnEmptyLogAWarning() throws Exception {
        Path train = scenes("train", 1, 50);
        Path empty = scenes("empty", 2, 0);
        assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", train, "--test", empty));
        oneLine(empty + ": holds no scenes");
        assertFalse(cli.out().contains("NaN"), cli.out());
        Path log = text("empty.lsf", "");
        assertEquals(ExitCodes.OK, cli.run("convert", log, "-o", dir.resolve("e.json")));
        assertTrue(cli.err().contains("warning: " + log + " is empty"), cli.err());
    }

    @Test
    void decisionTimesAreAllOverTheSameDecisions() throws Exception {
        Path train = scenes("train", 1, 200);
        Path test = scenes("test", 2, 150);
        assertEquals(ExitCodes.OK, cli.run("validate", "--train", train, "--test", test, "--json"), cli.err());
        JsonNode time = ConfigFiles.JSON.readTree(cli.out()).get("decisionMicros");
        assertEquals(150, time.get("decisions").asInt());
        assertTrue(time.get("p99").asDouble() <= time.get("max").asDouble(), time.toString());
        assertTrue(time.get("mean").asDouble() <= time.get("max").asDouble(), time.toString());
        assertEquals(ExitCodes.OK, cli.run("validate", "--train", train, "--test", test), cli.err());
        assertTrue(cli.out().contains("all over the same 150 decisions"), cli.out());
    }

    @Test
    void foldsPrintMacroF1AsTheFractionThePooledTablePrints() throws Exception {
        Path a = scenes("a", 1, 100);
        Path b = scenes("b", 2, 100);
        assertEquals(ExitCodes.OK, cli.run("validate", "--folds", a, b), cli.err());
        String row = cli.out().lines().filter(l -> l.strip().startsWith("macroF1")).findFirst().orElseThrow();
        assertFalse(row.contains("%"), row);
        double mean = Double.parseDouble(row.strip().split("\\s+")[1]);
        assertTrue(mean >= 0 && mean <= 1, row);
    }

    // ---- unbounded input and standard input ---------------------------------------------------

    @Test
    void aLineLongerThanTheCapStopsWithTheCapInTheMessage() throws Exception {
        Path log = dir.resolve("zeros.lsf");
        byte[] zeros = new byte[(1 << 20) + 10];
        Files.write(log, zeros);
        assertEquals(ExitCodes.FAILURE, cli.run("convert", log, "-o", dir.resolve("z.json")));
        oneLine(log + ":1: line longer than 1048576 bytes");
        assertFalse(Files.exists(dir.resolve("z.json")));
    }

    @Test
    void convertReadsStandardInputAsDash() throws Exception {
        InputStream before = System.in;
        try {
            System.setIn(new ByteArrayInputStream(SMALL_LOG.getBytes(StandardCharsets.US_ASCII)));
            assertEquals(ExitCodes.OK, cli.run("convert", "-", "-o", dir.resolve("stdin.json")), cli.err());
        } finally {
            System.setIn(before);
        }
        assertTrue(cli.out().contains("Scenes written         2"), cli.out());
    }

    // ---- half-written files and unclear errors ------------------------------------------------

    @Test
    void aTruncatedGzipIsNamed() throws Exception {
        Path log = dir.resolve("log.lsf.gz");
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(log))) {
            for (int i = 0; i < 2000; i++) {
                out.write(("(see " + i + " ((b) " + (i % 30) + " " + (i % 17) + "))\n(dash " + i + ")\n").getBytes(StandardCharsets.US_ASCII));
            }
        }
        byte[] whole = Files.readAllBytes(log);
        Files.write(log, Arrays.copyOf(whole, whole.length / 2));
        assertEquals(ExitCodes.FAILURE, cli.run("convert", log, "-o", dir.resolve("g.json")));
        oneLine(log + ": corrupt or truncated gzip");
        assertFalse(Files.exists(dir.resolve("g.json")));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(), files.filter(f -> f.getFileName().toString().endsWith(".tmp")).toList());
        }
    }

    @Test
    void outputsThatCannotBeWrittenAreRefusedBeforeTheWork() throws Exception {
        Path log = text("small.lsf", SMALL_LOG);
        Path file = text("full.lsf", SMALL_LOG);
        assertEquals(ExitCodes.USAGE, cli.run("convert", log, "--out-dir", file));
        oneLine("--out-dir " + file + ": is a file, not a directory");
        assertEquals(ExitCodes.USAGE, cli.run("convert", log, "-o", file.resolve("x.json")));
        oneLine(file + " is a file, not a directory");
        // the chart's name is checked before the training files are even read
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--train", dir.resolve("absent.json"), "--self", "--chart", dir.resolve("x.gif")));
        oneLine("--chart", "must end in .png or .svg");
        Path a = scenes("a", 1, 30);
        Path b = scenes("b", 2, 30);
        assertEquals(ExitCodes.USAGE, cli.run("tune", "--train", a, b, "-o", file.resolve("c.json"), "--quiet"));
        oneLine("-o", file + " is a file, not a directory");
        assertEquals("", cli.out(), "no configuration was tried");
    }

    @Test
    void controlCharactersOfALogAreEscapedInMessages() throws Exception {
        Path log = dir.resolve("random.lsf");
        Files.write(log, new byte[] {'x', 0x1b, '[', '2', 'J', 0x07, 'y', '\n'});
        assertEquals(ExitCodes.FAILURE, cli.run("convert", log, "-o", dir.resolve("r.json")));
        oneLine(log + ":1: not a player log", "\\x1B[2J\\x07y");
        assertFalse(cli.err().chars().anyMatch(c -> c < 0x20 && c != '\n' && c != '\r'), cli.err());
    }

    @Test
    void anUnknownOptionIsAUsageErrorWhereverItStands() throws Exception {
        Path a = scenes("a", 1, 30);
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--train", a, "--frobnicate", "--test", a));
        assertTrue(cli.err().contains("Unknown option: '--frobnicate'"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("validate", "--train", a, "--self", "--frobnicate"));
        assertTrue(cli.err().contains("--frobnicate"), cli.err());
    }

    @Test
    void showOfOneSceneStillReportsATruncatedFile() throws Exception {
        Path whole = scenes("whole", 1, 100);
        byte[] bytes = Files.readAllBytes(whole);
        Path truncated = dir.resolve("truncated.json");
        Files.write(truncated, Arrays.copyOf(bytes, bytes.length * 2 / 3));
        assertEquals(ExitCodes.FAILURE, cli.run("show", truncated, "--index", 3));
        oneLine(truncated + ":", "truncated");
        assertTrue(cli.out().contains("#3"), "the scene asked for is still shown");
    }

    @Test
    void jarsOnThePluginPathThatAreNoPluginOrCorruptAreWarnedOfOnce() throws Exception {
        Path plugins = Files.createDirectories(dir.resolve("plugins"));
        Files.write(plugins.resolve("corrupt.jar"), new byte[] {1, 2, 3});
        try (var jar = new java.util.jar.JarOutputStream(Files.newOutputStream(plugins.resolve("library.jar")))) {
            jar.putNextEntry(new java.util.jar.JarEntry("org/example/Nothing.txt"));
            jar.write('x');
        }
        List<String> warnings = new ArrayList<>(PluginRegistry.load(List.of(plugins)).warnings());
        assertEquals(2, warnings.size(), warnings.toString());
        assertTrue(warnings.get(0).startsWith(plugins.resolve("corrupt.jar") + ": not a readable jar"), warnings.get(0));
        assertTrue(warnings.get(1).startsWith(plugins.resolve("library.jar") + ": holds no scenes plugin"), warnings.get(1));
    }
}
