package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.GZIPOutputStream;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.app.Progress;
import org.scenes.app.convert.ArchiveConversion;
import org.scenes.app.convert.ConvertSettings;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.vision.Fading;

/**
 * {@code scenes convert ARCHIVE_DIR --out-dir DIR} over an archive of the simulator's own games
 * (nested directories, some gzipped, one without its command log), and {@code scenes stats DIR}.
 */
@Tag("slow")
class ConvertArchiveTest {
    /** The simulator's recorded name: {@code Ants_2-vs-Bees_1.rcg}. */
    private static final Pattern SCORE = Pattern.compile("Ants_(\\d+)-vs-Bees_(\\d+)");

    @TempDir
    static Path shared;
    /** Three games with their command logs (one gzipped, nested two deep) and one game log alone. */
    private static Path archive;

    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    @BeforeAll
    static void simulatedArchive() throws IOException {
        archive = shared.resolve("archive");
        CommandRunner cli = new CommandRunner();
        String[] places = {"round1", "round1/late", "round2", "round3"};
        for (int i = 0; i < places.length; i++) {
            assertEquals(0, cli.run("simulate", "--teams", "krislet:2,krislet:2", "--names", "Ants,Bees", "--cycles",
                    "300", "--seed", i + 1, "--out-dir", shared.resolve("players" + i), "--record",
                    archive.resolve(places[i])), cli.err());
        }
        for (Path log : gameLogs(archive.resolve("round1/late"))) {
            gzip(log);
            gzip(log.resolveSibling(log.getFileName().toString().replace(".rcg", ".rcl")));
        }
        for (Path log : gameLogs(archive.resolve("round3"))) {
            Files.delete(log.resolveSibling(log.getFileName().toString().replace(".rcg", ".rcl")));
        }
    }

    private static List<Path> gameLogs(Path directory) throws IOException {
        try (Stream<Path> files = Files.list(directory)) {
            return files.filter(f -> f.getFileName().toString().endsWith(".rcg")).toList();
        }
    }

    private static void gzip(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file);
             OutputStream out = new GZIPOutputStream(Files.newOutputStream(file.resolveSibling(file.getFileName() + ".gz")))) {
            in.transferTo(out);
        }
        Files.delete(file);
    }

    /** The archive copied, so a test may break a game of its own. */
    private Path copy() throws IOException {
        Path copy = dir.resolve("archive");
        try (Stream<Path> files = Files.walk(archive)) {
            for (Path file : files.toList()) {
                Path target = copy.resolve(archive.relativize(file).toString());
                if (Files.isDirectory(file)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(file, target);
                }
            }
        }
        return copy;
    }

    private static List<CSVRecord> manifest(Path out) throws IOException {
        try (Reader in = Files.newBufferedReader(out.resolve("manifest.csv"))) {
            return CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).build().parse(in).getRecords();
        }
    }

    private static List<Path> files(Path root) throws IOException {
        try (Stream<Path> files = Files.walk(root)) {
            return files.filter(Files::isRegularFile).sorted().toList();
        }
    }

    private static long scenes(Path file) {
        long count = 0;
        try (SceneFileReader reader = SceneFileReader.open(file)) {
            while (reader.hasNext()) {
                reader.next();
                count++;
            }
        }
        return count;
    }

    @Test
    void aGameWithoutItsCommandLogIsConvertedFromItsGameLogAloneByDefault() throws IOException {
        Path out = dir.resolve("auto");
        assertEquals(0, cli.run("convert", archive, "--out-dir", out, "--threads", 1), cli.err());
        assertTrue(cli.out().contains("Converted              4 (0 of them by an earlier run"), cli.out());
        for (CSVRecord row : manifest(out)) {
            assertEquals("converted", row.get("status"), row.toString());
            assertEquals(row.get("path").startsWith("round3/") ? "infer" : "rcl", row.get("commands"), row.toString());
        }
        Path inferred = dir.resolve("inferred");
        assertEquals(0, cli.run("convert", archive, "--out-dir", inferred, "--commands", "infer", "--threads", 1),
                cli.err());
        for (CSVRecord row : manifest(inferred)) {
            assertEquals("infer", row.get("commands"), row.toString());
        }
    }

    @Test
    void convertsEveryPlayerOfEveryGameGroupedByTeamWithAManifestThenResumes() throws IOException {
        Path out = dir.resolve("scenes");
        assertEquals(0, cli.run("convert", archive, "--commands", "rcl", "--out-dir", out, "--threads", 1), cli.err());
        assertTrue(cli.out().contains("Converted              3 (0 of them by an earlier run"), cli.out());
        assertTrue(cli.err().contains("skipped: no command log beside it"), cli.err());

        List<CSVRecord> rows = manifest(out);
        assertEquals(4, rows.size());
        Map<String, CSVRecord> byGame = new HashMap<>();
        for (CSVRecord row : rows) {
            byGame.put(row.get("game"), row);
        }
        List<String> converted = new ArrayList<>();
        for (CSVRecord row : rows) {
            Matcher score = SCORE.matcher(row.get("path"));
            assertTrue(score.find(), row.get("path"));
            if (row.get("path").startsWith("round3/")) {
                assertEquals("skipped", row.get("status"));
                assertTrue(row.get("reason").contains("no command log"), row.get("reason"));
                assertEquals("0", row.get("players"));
                continue;
            }
            assertEquals("converted", row.get("status"), row.toString());
            assertEquals("Ants", row.get("left_team"));
            assertEquals("Bees", row.get("right_team"));
            assertEquals(score.group(1), row.get("left_score"));
            assertEquals(score.group(2), row.get("right_score"));
            assertEquals("4", row.get("players"));
            assertEquals("rcl", row.get("commands"));
            assertEquals("", row.get("reason"));
            // the grouped layout: DIR/TEAM/GAME_UNUM.json.gz, and the manifest counts the scenes in them
            String game = row.get("game");
            long scenes = 0;
            for (String player : List.of("Ants/" + game + "_1", "Ants/" + game + "_2", "Bees/" + game + "_1",
                    "Bees/" + game + "_2")) {
                Path file = out.resolve(player + ".json.gz");
                assertTrue(Files.isRegularFile(file), file.toString());
                scenes += scenes(file);
            }
            assertTrue(scenes > 0);
            assertEquals(Long.toString(scenes), row.get("scenes"));
            converted.add(game);
        }
        assertEquals(3, converted.size());
        // nested directories name the game; the gzipped pair converted as the plain ones
        assertTrue(converted.stream().anyMatch(g -> g.startsWith("round1-late-Ants_")), converted.toString());
        assertEquals(12, files(out.resolve("Ants")).size() + files(out.resolve("Bees")).size());

        // a second run converts nothing again: every file stays as it was
        Map<Path, FileTime> times = new HashMap<>();
        for (Path file : files(out.resolve("Ants"))) {
            times.put(file, Files.getLastModifiedTime(file));
        }
        assertEquals(0, cli.run("convert", archive, "--commands", "rcl", "--out-dir", out), cli.err());
        assertTrue(cli.out().contains("Converted              3 (3 of them by an earlier run"), cli.out());
        for (Map.Entry<Path, FileTime> file : times.entrySet()) {
            assertEquals(file.getValue(), Files.getLastModifiedTime(file.getKey()), file.getKey().toString());
        }
        assertEquals(rows.toString(), manifest(out).toString());

        // stats over the archive's output: per team, its games and its action mix
        assertEquals(0, cli.run("stats", out), cli.err());
        String stats = cli.out();
        assertTrue(stats.contains("(2 teams)"), stats);
        long antsScenes = files(out.resolve("Ants")).stream().mapToLong(ConvertArchiveTest::scenes).sum();
        Matcher ants = Pattern.compile("(?m)^Ants +3 +(\\d+) +(\\d+) +(\\d+) +6 +" + antsScenes + " +(.*)$").matcher(stats);
        assertTrue(ants.find(), stats);
        assertTrue(Pattern.compile("(?m)^Bees +3 ").matcher(stats).find(), stats);
        assertTrue(stats.contains("dash %") && stats.contains("turn %"), stats);
        double share = 0;
        for (String percent : ants.group(4).trim().split(" +")) {
            share += Double.parseDouble(percent);
        }
        assertEquals(100, share, 0.5, stats);
    }

    @Test
    void aGameThatFailsIsRecordedWithItsReasonAndLeavesNoFile() throws IOException {
        Path copy = copy();
        // round2's game log out of order: two shows swapped
        Path broken = gameLogs(copy.resolve("round2")).get(0);
        List<String> lines = new ArrayList<>(Files.readAllLines(broken, StandardCharsets.UTF_8));
        int first = -1;
        for (int i = lines.size() / 2; i < lines.size(); i++) {
            if (lines.get(i).startsWith("(show ")) {
                if (first < 0) {
                    first = i;
                } else {
                    lines.set(first, lines.set(i, lines.get(first)));
                    break;
                }
            }
        }
        Files.write(broken, lines, StandardCharsets.UTF_8);
        String game = "round2-" + broken.getFileName().toString().replace(".rcg", "");

        Path out = dir.resolve("scenes");
        assertEquals(1, cli.run("convert", copy, "--commands", "rcl", "--out-dir", out, "--threads", 1), cli.err());
        assertTrue(cli.err().contains("scenes: error: 1 of 4 games failed"), cli.err());
        CSVRecord row = manifest(out).stream().filter(r -> r.get("game").equals(game)).findFirst().orElseThrow();
        assertEquals("failed", row.get("status"));
        assertTrue(row.get("reason").contains(broken.getFileName().toString()), row.get("reason"));
        assertTrue(cli.err().contains(row.get("reason")), cli.err());
        assertEquals(2, manifest(out).stream().filter(r -> r.get("status").equals("converted")).count());
        for (Path file : files(out)) {
            assertFalse(file.getFileName().toString().startsWith(game), file.toString());
            assertFalse(file.getFileName().toString().endsWith(".tmp"), file.toString());
        }
        // the next run tries the failed game again, and only it
        assertEquals(1, cli.run("convert", copy, "--commands", "rcl", "--out-dir", out));
        assertTrue(cli.out().contains("Converted              2 (2 of them by an earlier run"), cli.out());
    }

    @Test
    void aRunStoppedMidwayLeavesNoPartialFileAndTheNextRunResumes() throws IOException {
        Path out = dir.resolve("scenes");
        // the first game's Bees 2 cannot be published (its name taken by a directory): the game's files
        // were being committed when its output failed
        String[] firstGame = {null};
        try (Stream<Path> files = Files.walk(archive)) {
            Path rcg = files.filter(f -> f.getFileName().toString().matches(".*\\.rcg(\\.gz)?")).sorted().findFirst()
                    .orElseThrow();
            firstGame[0] = archive.relativize(rcg).toString().replaceFirst("\\.rcg(\\.gz)?$", "").replace('/', '-');
        }
        Path blocked = Files.createDirectories(out.resolve("Bees/" + firstGame[0] + "_2.json.gz"));
        assertEquals(1, cli.run("convert", archive, "--commands", "rcl", "--out-dir", out, "--threads", 1), cli.err());
        assertTrue(cli.err().contains(firstGame[0]) || cli.err().contains("round1"), cli.err());
        for (Path file : files(out)) {
            assertFalse(file.getFileName().toString().startsWith(firstGame[0]), file.toString());
            assertFalse(file.getFileName().toString().endsWith(".tmp"), file.toString());
        }
        Files.delete(blocked);

        // a run stopped between games (its progress callback throws): the games done stay, with their records
        ConvertSettings settings = new ConvertSettings(Grid.DEFAULT, Pairing.AUTO, false, false, false,
                Fading.named("dice", 1), GameLogConverter.everyone(), false, GameLogConverter.SeePhase.INFER, 1,
                SceneCompression.GZIP);
        Path stopped = dir.resolve("stopped");
        RuntimeException stop = assertThrows(RuntimeException.class, () -> new ArchiveConversion(
                new ArchiveConversion.Request(archive, stopped, settings, GameLogs.Commands.RCL)).run(new Progress() {
                    private int steps;

                    @Override
                    public void begin(String task, long total) {
                    }

                    @Override
                    public void step() {
                        if (++steps == 2) {
                            throw new IllegalStateException("stopped");
                        }
                    }

                    @Override
                    public void end() {
                    }
                }));
        assertEquals("stopped", stop.getMessage());
        assertFalse(Files.exists(stopped.resolve("manifest.csv")));
        assertEquals(8, files(stopped.resolve("Ants")).size() + files(stopped.resolve("Bees")).size());
        ArchiveConversion.Result resumed = new ArchiveConversion(new ArchiveConversion.Request(archive, stopped,
                settings, GameLogs.Commands.RCL)).run(Progress.NONE);
        assertEquals(2, resumed.resumed());
        assertEquals(3, resumed.count(org.scenes.app.convert.ManifestRow.Status.converted));
        assertEquals(12, files(stopped.resolve("Ants")).size() + files(stopped.resolve("Bees")).size());
        // the blocked game converted once its output can be written, the others kept
        assertEquals(0, cli.run("convert", archive, "--commands", "rcl", "--out-dir", out, "--threads", 1), cli.err());
        assertTrue(cli.out().contains("Converted              3 (2 of them by an earlier run"), cli.out());
        assertEquals(12, files(out.resolve("Ants")).size() + files(out.resolve("Bees")).size());
    }

    /**
     * A child JVM converting an archive of 40 games, stopped by SIGTERM once its first game is
     * recorded: it says how far it got, leaves no temporary file and no broken scene file, and
     * the next run converts the rest into what an uninterrupted run writes.
     */
    @Test
    void aConvertStoppedBySigtermResumesIntoTheFilesOfAnUninterruptedRun() throws Exception {
        Path many = dir.resolve("many");
        for (int copy = 0; copy < 10; copy++) {
            try (Stream<Path> files = Files.walk(archive)) {
                for (Path file : files.filter(Files::isRegularFile).toList()) {
                    Path target = many.resolve("copy" + copy).resolve(archive.relativize(file).toString());
                    Files.createDirectories(target.getParent());
                    Files.copy(file, target);
                }
            }
        }
        Path out = dir.resolve("stopped");
        Path records = out.resolve(".games");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-cp", System.getProperty("java.class.path"), "org.scenes.cli.Main", "convert",
                many.toString(), "--commands", "rcl", "--out-dir", out.toString(), "--threads", "1"));
        Path childOut = dir.resolve("child.out");
        Process child = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(childOut.toFile()).start();
        // the condition: a game recorded (polled; the child needs seconds for 30 games)
        while (child.isAlive() && !(Files.isDirectory(records) && hasFile(records))) {
            Thread.sleep(20);
        }
        child.destroy();
        assertTrue(child.waitFor(120, java.util.concurrent.TimeUnit.SECONDS));
        String said = Files.readString(childOut);
        assertTrue(said.contains("scenes: interrupted: ") && said.contains(" of 40 games done; run the same command again"),
                said);
        assertFalse(Files.exists(out.resolve("manifest.csv")), said);
        for (Path file : files(out)) {
            assertFalse(file.getFileName().toString().endsWith(".tmp"), file.toString());
            if (file.getFileName().toString().endsWith(".json.gz")) {
                assertTrue(scenes(file) > 0, file.toString());
            }
        }

        assertEquals(0, cli.run("convert", many, "--commands", "rcl", "--out-dir", out, "--threads", 1), cli.err());
        Matcher resumed = Pattern.compile("Converted +30 \\((\\d+) of them by an earlier run").matcher(cli.out());
        assertTrue(resumed.find() && Integer.parseInt(resumed.group(1)) >= 1, cli.out());
        Path whole = dir.resolve("whole");
        assertEquals(0, cli.run("convert", many, "--commands", "rcl", "--out-dir", whole, "--threads", 1), cli.err());
        List<Path> expected = files(whole);
        assertEquals(expected.stream().map(whole::relativize).toList(), files(out).stream().map(out::relativize).toList());
        for (Path file : expected) {
            assertEquals(text(file), text(out.resolve(whole.relativize(file).toString())), file.toString());
        }
        assertEquals(Files.readString(whole.resolve("manifest.csv")), Files.readString(out.resolve("manifest.csv")));
    }

    @Test
    void badArchivesAndOutputsAreUsageErrorsBeforeAnyWork() throws IOException {
        Path empty = Files.createDirectories(dir.resolve("empty"));
        assertEquals(2, cli.run("convert", empty, "--out-dir", dir.resolve("out")));
        assertTrue(cli.err().contains("no game logs (.rcg, .rcg.gz) under " + empty), cli.err());
        assertFalse(Files.exists(dir.resolve("out")));
        assertEquals(2, cli.run("convert", archive, "-o", dir.resolve("all.json")));
        assertTrue(cli.err().contains("is converted into --out-dir DIR"), cli.err());
        Path copy = copy();
        assertEquals(2, cli.run("convert", copy, "--out-dir", copy));
        assertTrue(cli.err().contains("is the archive"), cli.err());
        assertEquals(2, cli.run("stats", empty));
        assertTrue(cli.err().contains("a directory without manifest.csv"), cli.err());
    }

    /** A file's text, gunzipped when gzipped. */
    private static String text(Path file) throws IOException {
        try (InputStream in = org.scenes.internal.files.Inputs.open(file)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private static boolean hasFile(Path directory) throws IOException {
        try (Stream<Path> files = Files.list(directory)) {
            return files.anyMatch(f -> f.getFileName().toString().endsWith(".json"));
        }
    }
}
