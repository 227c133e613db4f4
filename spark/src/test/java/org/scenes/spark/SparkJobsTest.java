package org.scenes.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.files.Inputs;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * The Spark jobs give the local commands' rows on the same input: scene files of a seeded
 * simulated game ({@code scenes convert}), sweep tables ({@code scenes experiment}) and the tuned
 * configuration ({@code scenes tune}). Spark runs in local mode on two threads, as CI runs it.
 */
@Tag("slow")
class SparkJobsTest {
    @TempDir
    static Path work;
    static Path games;
    /** The server's logs of game1: its .rcg and .rcl. */
    static List<Path> serverLogs;

    /**
     * Two short seeded games of three Krislet players a side, each in its own directory of player
     * logs; the first also recorded as the server's logs.
     */
    @BeforeAll
    static void games() throws IOException {
        games = work.resolve("games");
        for (int seed = 1; seed <= 2; seed++) {
            Path game = games.resolve("game" + seed);
            Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Carleton", 3, Teachers.byName("krislet")),
                    new GameSetup.Team("University", 3, Teachers.byName("krislet")), 1000, seed, game));
            if (seed == 1) {
                simulator.recordTo(work.resolve("server"));
            }
            simulator.run(t -> { });
            if (seed == 1) {
                serverLogs = simulator.recorded();
            }
        }
    }

    record Run(int status, String out, String err) {
    }

    static Run local(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = org.scenes.cli.Main.run(new PrintWriter(out), new PrintWriter(err), args);
        return new Run(status, out.toString(), err.toString());
    }

    static Run spark(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        List<String> all = new ArrayList<>(List.of("--master", "local[2]"));
        all.addAll(List.of(args));
        int status = SparkCommand.run(new PrintWriter(out), new PrintWriter(err), all.toArray(String[]::new));
        return new Run(status, out.toString(), err.toString());
    }

    static String gunzip(Path file) throws IOException {
        try (InputStream in = new GZIPInputStream(Files.newInputStream(file))) {
            return new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        }
    }

    static List<Path> files(Path directory) throws IOException {
        try (Stream<Path> walk = Files.walk(directory)) {
            return walk.filter(Files::isRegularFile).sorted().toList();
        }
    }

    @Test
    void convertWritesTheScenesOfScenesConvertOneTaskPerGame() throws IOException {
        Path out = work.resolve("spark-scenes");
        Run job = spark("convert", games.toString(), "--out-dir", out.toString());
        assertEquals(0, job.status(), job.err());
        assertTrue(job.out().contains("Games                  2 (one task each)"), job.out());
        assertEquals(12, files(out).size(), "one scene file per player log, nothing else (no temporary or checksum files)");
        for (int seed = 1; seed <= 2; seed++) {
            Path game = games.resolve("game" + seed);
            List<String> logs = new ArrayList<>();
            try (Stream<Path> list = Files.list(game)) {
                list.filter(p -> p.toString().endsWith(".lsf.gz")).sorted().forEach(p -> logs.add(p.toString()));
            }
            Path expected = work.resolve("local-scenes/game" + seed);
            List<String> args = new ArrayList<>(List.of("convert"));
            args.addAll(logs);
            args.addAll(List.of("--out-dir", expected.toString()));
            Run convert = local(args.toArray(String[]::new));
            assertEquals(0, convert.status(), convert.err());
            for (Path file : files(expected)) {
                Path written = out.resolve("game" + seed).resolve(file.getFileName());
                assertEquals(gunzip(file), gunzip(written), written.toString());
            }
        }
    }

    @Test
    void convertTakesGameLogsPlainOrGzippedAndWritesTheScenesOfScenesConvert() throws IOException {
        assertEquals(2, serverLogs.size(), "a game log and a command log");
        Path gameLog = serverLogs.get(0);
        String base = gameLog.getFileName().toString().replaceFirst("\\.rcg$", "");
        // the same game gzipped under another name, given by name (its command log is found beside it)
        Path zipped = Files.createDirectories(work.resolve("server-gz"));
        for (Path log : serverLogs) {
            String suffix = log.getFileName().toString().endsWith(".rcg") ? ".rcg.gz" : ".rcl.gz";
            try (var out = new java.util.zip.GZIPOutputStream(Files.newOutputStream(zipped.resolve("zipped" + suffix)))) {
                Files.copy(log, out);
            }
        }
        Path out = work.resolve("spark-game-scenes");
        Run job = spark("convert", gameLog.getParent().toString(), zipped.resolve("zipped.rcg.gz").toString(),
                "--out-dir", out.toString(), "--commands-first");
        assertEquals(0, job.status(), job.err());
        assertTrue(job.out().contains("Games                  2 (one task each)"), job.out());
        for (Path input : List.of(gameLog, zipped.resolve("zipped.rcg.gz"))) {
            String name = input.getFileName().toString().startsWith("zipped") ? "zipped" : base;
            Path expected = work.resolve("local-game-scenes/" + name);
            Run convert = local("convert", input.toString(), "--out-dir", expected.toString(), "--commands-first");
            assertEquals(0, convert.status(), convert.err());
            List<Path> local = files(expected);
            assertEquals(6, local.size(), "a scene file per player");
            List<Path> written = files(out.resolve(name));
            assertEquals(local.stream().map(Path::getFileName).toList(), written.stream().map(Path::getFileName).toList(),
                    "the same players' files, nothing else");
            for (Path file : local) {
                assertEquals(gunzip(file), gunzip(out.resolve(name).resolve(file.getFileName())), file.toString());
            }
        }
        assertEquals(12, files(out).size());
    }

    @Test
    void convertWritesZstdScenesAsScenesConvertDoesWhenAsked() throws IOException {
        Path gameLog = serverLogs.get(0);
        String base = gameLog.getFileName().toString().replaceFirst("\\.rcg$", "");
        Path out = work.resolve("spark-zstd-scenes");
        Run job = spark("convert", gameLog.toString(), "--out-dir", out.toString(), "--compression", "zstd");
        assertEquals(0, job.status(), job.err());
        Path expected = work.resolve("local-zstd-scenes");
        Run convert = local("convert", gameLog.toString(), "--out-dir", expected.toString(), "--compression", "zstd");
        assertEquals(0, convert.status(), convert.err());
        List<Path> local = files(expected);
        assertEquals(6, local.size(), "a scene file per player");
        for (Path file : local) {
            assertTrue(file.getFileName().toString().endsWith(".json.zst"), file.toString());
            try (InputStream a = Inputs.open(file); InputStream b = Inputs.open(out.resolve(base).resolve(file.getFileName()))) {
                assertEquals(new String(a.readAllBytes(), StandardCharsets.UTF_8), new String(b.readAllBytes(),
                        StandardCharsets.UTF_8), file.toString());
            }
        }
    }

    @Test
    void aCommandLogWithoutItsGameLogIsAUsageError() {
        Run job = spark("convert", serverLogs.get(1).toString(), "--out-dir", work.resolve("no-game").toString());
        assertEquals(2, job.status(), job.err());
        assertTrue(job.err().startsWith("scenes-spark: " + serverLogs.get(1) + " is a command log"), job.err());
        assertFalse(Files.exists(work.resolve("no-game")));
    }

    @Test
    void experimentRowsEqualScenesExperiment() throws IOException {
        Path data = work.resolve("sweep-data");
        Run convert = local("convert", games.resolve("game1").resolve("Carleton_1.lsf.gz").toString(),
                games.resolve("game1").resolve("Carleton_2.lsf.gz").toString(),
                games.resolve("game1").resolve("Carleton_3.lsf.gz").toString(), "--out-dir", data.toString());
        assertEquals(0, convert.status(), convert.err());
        // a seeded random selector and a memory transform: numbers that depend on seed, order and sequences
        Path sweep = Files.writeString(work.resolve("sweep.groovy"), """
                title 'Spark against local'
                data '%1$s/Carleton_1.json.gz', '%1$s/Carleton_2.json.gz', '%1$s/Carleton_3.json.gz'
                metrics 'ball-goal', 'cell'
                k 1, 3
                selectors 'first-valid', 'vote-random'
                protocol 'leave-one-out'
                transforms 'memory'
                seed 3
                table columns: 'k'
                """.formatted(data.toString().replace("\\", "/")));
        Run expected = local("experiment", sweep.toString(), "--out-dir", work.resolve("local-results").toString(),
                "--threads", "2");
        assertEquals(0, expected.status(), expected.err());
        Run job = spark("experiment", sweep.toString(), "--out-dir", work.resolve("spark-results").toString());
        assertEquals(0, job.status(), job.err());

        assertEquals(Files.readString(work.resolve("local-results/sweep.csv")),
                Files.readString(work.resolve("spark-results/sweep.csv")));
        ObjectMapper json = new ObjectMapper();
        ObjectNode local = (ObjectNode) json.readTree(work.resolve("local-results/sweep.json").toFile());
        ObjectNode distributed = (ObjectNode) json.readTree(work.resolve("spark-results/sweep.json").toFile());
        assertTrue(distributed.get("command").asText().startsWith("scenes-spark experiment "));
        local.remove("command");
        distributed.remove("command");
        assertEquals(local, distributed);
        String table = Files.readString(work.resolve("local-results/sweep.md"));
        String sparkTable = Files.readString(work.resolve("spark-results/sweep.md"));
        String pivot = table.substring(table.indexOf("| metric"), table.indexOf("\n!["));
        assertTrue(sparkTable.endsWith(pivot), sparkTable);
        assertEquals(8 + 1, Files.readAllLines(work.resolve("spark-results/sweep.csv")).size());
        // one knowledge base per fold on the (only) executor, not one per task
        assertEquals(3, ExecutorState.knowledgeBases());
    }

    @Test
    void tuneChoosesTheConfigurationOfScenesTune() throws IOException {
        Path data = work.resolve("tune-data");
        Run convert = local("convert", games.resolve("game2").resolve("Carleton_1.lsf.gz").toString(),
                games.resolve("game2").resolve("Carleton_2.lsf.gz").toString(), "--out-dir", data.toString());
        assertEquals(0, convert.status(), convert.err());
        String one = data.resolve("Carleton_1.json.gz").toString();
        String two = data.resolve("Carleton_2.json.gz").toString();
        Run expected = local("tune", "--train", one, two, "--sweeps", "1", "--quiet", "-o", work.resolve("local.json").toString());
        assertEquals(0, expected.status(), expected.err());
        Run job = spark("tune", "--train", one, two, "--sweeps", "1", "--quiet", "-o", work.resolve("spark.json").toString());
        assertEquals(0, job.status(), job.err());
        ObjectMapper json = new ObjectMapper();
        ObjectNode local = (ObjectNode) json.readTree(work.resolve("local.json").toFile());
        ObjectNode distributed = (ObjectNode) json.readTree(work.resolve("spark.json").toFile());
        for (ObjectNode config : List.of(local, distributed)) {
            ((ObjectNode) config.get("crossValidation").get("figures")).remove("meanDecisionMicros");
        }
        assertEquals(local, distributed);
        assertTrue(job.out().startsWith("Best of " + local.get("crossValidation").get("configurationsTried").asInt()
                + " configurations: "), job.out());
    }

    @Test
    void aMissingSweepFileIsAUsageErrorBeforeAnyJob() throws IOException {
        Path sweep = Files.writeString(work.resolve("missing.groovy"), """
                data 'no-such-file.json.gz', 'neither.json.gz'
                metrics 'ball-goal'
                k 1
                selectors 'first-valid'
                """);
        Run job = spark("experiment", sweep.toString());
        assertEquals(2, job.status());
        assertEquals(1, job.err().lines().count(), job.err());
        assertTrue(job.err().startsWith("scenes-spark: the sweep's scene file no-such-file.json.gz does not exist"), job.err());
        assertFalse(Files.exists(work.resolve("missing.csv")));
    }
}
