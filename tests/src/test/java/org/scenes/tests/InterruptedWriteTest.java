package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedWriter;
import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;

/**
 * A child JVM running {@code scenes convert} or {@code scenes simulate} is stopped at random
 * points, with SIGTERM (Ctrl-C's effect) or SIGKILL: afterwards each output is the old file or
 * the complete new one, never a broken one, and no temporary file is left: none after SIGTERM,
 * and after SIGKILL (which runs no code) none once the next writer has run.
 */
@Tag("slow")
class InterruptedWriteTest {
    private static final int SEES = 150_000;
    @TempDir
    static Path dir;
    private static Path bigLog;
    private static Path smallLog;

    @BeforeAll
    static void logs() throws IOException {
        bigLog = lsf("big.lsf", SEES);
        smallLog = lsf("small.lsf", 50);
    }

    private static Path lsf(String name, int sees) throws IOException {
        Path file = dir.resolve(name);
        Random random = new Random(16);
        try (BufferedWriter out = Files.newBufferedWriter(file, StandardCharsets.US_ASCII)) {
            out.write("(init l 1 before_kick_off)\n");
            for (int i = 0; i < sees; i++) {
                out.write("(see " + i + " ((b) " + (1 + random.nextInt(40)) + " " + (random.nextInt(91) - 45)
                        + ") ((g r) " + (5 + random.nextInt(60)) + " " + (random.nextInt(91) - 45) + ") ((f c) 20 "
                        + (random.nextInt(91) - 45) + "))\n");
                out.write(random.nextBoolean() ? "(dash " + random.nextInt(100) + ")\n" : "(turn " + (random.nextInt(91) - 45) + ")\n");
            }
        }
        return file;
    }

    private static Process start(Path workDir, String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-cp", System.getProperty("java.class.path"), "org.scenes.cli.Main"));
        command.addAll(Arrays.asList(args));
        return new ProcessBuilder(command).directory(workDir.toFile()).redirectErrorStream(true)
                .redirectOutput(workDir.resolve("child.out").toFile()).start();
    }

    /** After {@code millis}, SIGKILL or SIGTERM; waits (bounded) until the child is gone. */
    private static void stop(Process child, long millis, boolean kill) throws InterruptedException {
        Thread.sleep(millis);
        if (kill) {
            child.destroyForcibly();
        } else {
            child.destroy();
        }
        assertTrue(child.waitFor(120, TimeUnit.SECONDS), "the child stops");
    }

    private static int run(Path workDir, String... args) throws Exception {
        Process process = start(workDir, args);
        assertTrue(process.waitFor(600, TimeUnit.SECONDS), "the child finishes: " + Arrays.toString(args));
        return process.exitValue();
    }

    /** One report writer: its arguments for a short (old) and a long (new) run, and when its output is whole. */
    private record Writer(String name, String target, List<String> oldRun, List<String> newRun,
            Predicate<String> complete) {
    }

    /**
     * The report writers (validate's chart, tune's configuration, experiment's result table,
     * evaluate's HTML report), stopped by SIGTERM or SIGKILL at random points: afterwards the old
     * file or the new one, never a broken one; no temporary file after SIGTERM, nor after SIGKILL
     * once the same command wrote again.
     */
    @Test
    void reportWritersStoppedAnywhereLeaveTheOldOrTheNewFile() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("report-scenes"));
        Path small = scenes.resolve("small.json.gz");
        Path[] parts = new Path[3];
        StringWriter out = new StringWriter();
        assertEquals(0, org.scenes.cli.Main.run(new PrintWriter(out), new PrintWriter(out), "convert",
                smallLog.toString(), "-o", small.toString()), out.toString());
        Path part = lsf("part.lsf", 6000);
        for (int i = 0; i < parts.length; i++) {
            parts[i] = scenes.resolve("part" + i + ".json.gz");
            assertEquals(0, org.scenes.cli.Main.run(new PrintWriter(out), new PrintWriter(out), "convert",
                    part.toString(), "-o", parts[i].toString()), out.toString());
        }
        String sweep = "title 'Interrupted'\ndata %s\nmetrics 'ball-goal'\nk 1, 5\nselectors 'first-valid'\n";
        Path oldSweep = Files.writeString(scenes.resolve("old.groovy"), sweep.formatted(quoted(small) + ", " + quoted(small)));
        Path newSweep = Files.writeString(scenes.resolve("new.groovy"), sweep.formatted(
                quoted(parts[0]) + ", " + quoted(parts[1]) + ", " + quoted(parts[2])));
        List<Writer> writers = List.of(
                new Writer("experiment", "results/sweep.csv",
                        List.of("experiment", oldSweep.toString(), "--out-dir", "results", "--name", "sweep"),
                        List.of("experiment", newSweep.toString(), "--out-dir", "results", "--name", "sweep"),
                        text -> text.endsWith("\n") && text.split("\n").length == 3),
                new Writer("evaluate --report", "report/index.html",
                        List.of("evaluate", "--players", "2", "--opponent", "krislet:2", "--cycles", "200", "--seeds", "1",
                                "--report", "report"),
                        List.of("evaluate", "--players", "2", "--opponent", "krislet:2", "--cycles", "800", "--seeds", "1",
                                "--report", "report"),
                        text -> text.strip().endsWith("</html>")),
                new Writer("validate --chart", "chart.svg",
                        List.of("validate", "--train", small.toString(), "--test", small.toString(), "--metric",
                                "ball-goal", "--chart", "chart.svg"),
                        List.of("validate", "--train", parts[0].toString(), "--test", parts[1].toString(), "--metric",
                                "ball-goal", "--metric", "cell", "--chart", "chart.svg"),
                        text -> text.strip().endsWith("</svg>")),
                new Writer("tune -o", "tuned.json",
                        List.of("tune", "--train", small.toString(), small.toString(), "-o", "tuned.json",
                                "--quiet", "--sweeps", "1"),
                        List.of("tune", "--train", parts[0].toString(), parts[1].toString(),
                                "-o", "tuned.json", "--quiet", "--sweeps", "1"),
                        InterruptedWriteTest::isJson));
        Random random = new Random(1618);
        int replaced = 0;
        int trials = 0;
        for (Writer writer : writers) {
            Path reference = Files.createDirectories(dir.resolve("reference-" + writer.target()));
            long started = System.nanoTime();
            assertEquals(0, run(reference, writer.newRun().toArray(String[]::new)),
                    writer.name() + ": " + Files.readString(reference.resolve("child.out")));
            long runMillis = (System.nanoTime() - started) / 1_000_000;
            assertTrue(writer.complete().test(Files.readString(reference.resolve(writer.target()))), writer.name());
            // two stops each (the child JVMs make this test long on a loaded machine): SIGTERM, then SIGKILL
            for (int trial = 0; trial < 2; trial++, trials++) {
                boolean kill = trial == 1;
                Path work = Files.createDirectories(dir.resolve("report-" + writer.target() + "-" + trial));
                Path target = work.resolve(writer.target());
                assertEquals(0, run(work, writer.oldRun().toArray(String[]::new)), Files.readString(work.resolve("child.out")));
                byte[] before = Files.readAllBytes(target);
                Process child = start(work, writer.newRun().toArray(String[]::new));
                stop(child, runMillis / 4 + (long) (random.nextDouble() * runMillis), kill);
                String output = Files.readString(work.resolve("child.out"));
                byte[] after = Files.readAllBytes(target);
                if (!Arrays.equals(before, after)) {
                    assertTrue(writer.complete().test(new String(after, StandardCharsets.UTF_8)),
                            writer.name() + ": a new file is whole: " + output);
                    replaced++;
                }
                if (kill) {
                    assertEquals(0, run(work, writer.oldRun().toArray(String[]::new)), "rerun");
                }
                assertEquals(List.of(), temporaries(work), writer.name() + (kill ? " after SIGKILL and a rerun" : " after SIGTERM"));
            }
        }
        System.out.println("InterruptedWriteTest: " + replaced + " of " + trials + " report writers finished before the signal");
    }

    private static String quoted(Path path) {
        return "'" + path.toString().replace("\\", "/") + "'";
    }

    private static boolean isJson(String text) {
        try (com.fasterxml.jackson.core.JsonParser parser = new com.fasterxml.jackson.core.JsonFactory().createParser(text)) {
            int tokens = 0;
            while (parser.nextToken() != null) {
                tokens++;
            }
            return tokens > 0;
        } catch (IOException e) {
            return false;
        }
    }

    private static List<Path> temporaries(Path directory) throws IOException {
        try (Stream<Path> files = Files.walk(directory)) {
            return files.filter(f -> f.getFileName().toString().endsWith(".tmp")).toList();
        }
    }

    @Test
    void aConvertStoppedAnywhereLeavesTheOldOrTheNewSceneFile() throws Exception {
        Random random = new Random(1616);
        // how long an uninterrupted run takes here and now: the stops are spread over it and a bit beyond
        Path reference = Files.createDirectories(dir.resolve("reference"));
        long started = System.nanoTime();
        Process whole = start(reference, "convert", bigLog.toString(), "-o", reference.resolve("scenes.json.gz").toString());
        assertTrue(whole.waitFor(600, TimeUnit.SECONDS) && whole.exitValue() == 0, Files.readString(reference.resolve("child.out")));
        long runMillis = (System.nanoTime() - started) / 1_000_000;
        assertEquals(SEES, SceneFileReader.read(reference.resolve("scenes.json.gz")).scenes().size());
        int trials = 8;
        int replaced = 0;
        for (int trial = 0; trial < trials; trial++) {
            boolean kill = trial % 4 == 3;
            Path work = Files.createDirectories(dir.resolve("convert-" + trial));
            Path target = work.resolve("scenes.json.gz");
            Process old = start(work, "convert", smallLog.toString(), "-o", target.toString());
            assertTrue(old.waitFor(120, TimeUnit.SECONDS) && old.exitValue() == 0, Files.readString(work.resolve("child.out")));
            byte[] before = Files.readAllBytes(target);

            Process child = start(work, "convert", bigLog.toString(), "-o", target.toString());
            // a random point of the run: JVM start, reading, writing, the rename, or after it
            stop(child, runMillis / 5 + (long) (random.nextDouble() * runMillis * 1.1), kill);
            String output = Files.readString(work.resolve("child.out"));
            byte[] after = Files.readAllBytes(target);
            if (!Arrays.equals(before, after)) {
                SceneFile file = SceneFileReader.read(target);
                assertEquals(SEES, file.scenes().size(), "a new file is complete: " + output);
                replaced++;
            } else {
                assertArrayEquals(before, after);
            }
            if (kill) {
                // SIGKILL ran no code: the next writer into the directory removes what it left
                assertTrue(run(work, "convert", smallLog.toString(), "-o", target.toString()) == 0, "rerun");
                assertEquals(List.of(), temporaries(work), "after SIGKILL and a rerun");
            } else {
                assertEquals(List.of(), temporaries(work), "after SIGTERM: " + output);
                // stopped before the command began (JVM start), during it (it says what it completed), or after it
                assertTrue(output.isBlank() || output.contains("interrupted: ") || output.contains("Written"),
                        "exit " + child.exitValue() + ": " + output);
            }
        }
        // what the random points reached is reported, not required (the machine's speed decides it)
        System.out.println("InterruptedWriteTest: " + replaced + " of " + trials + " converts finished before the signal"
                + " (an uninterrupted one took " + runMillis + " ms)");
    }

    @Test
    void aSimulationStoppedBySigtermLeavesNoHalfWrittenLog() throws Exception {
        Random random = new Random(1617);
        for (int trial = 0; trial < 3; trial++) {
            Path work = Files.createDirectories(dir.resolve("simulate-" + trial));
            Path logs = work.resolve("logs");
            Process child = start(work, "simulate", "--teams", "krislet:2,krislet:2", "--cycles", "6000",
                    "--seed", Integer.toString(trial + 1), "--out-dir", logs.toString());
            Thread.sleep(500 + random.nextInt(5000));
            child.destroy();
            assertTrue(child.waitFor(120, TimeUnit.SECONDS), "the child stops");
            assertEquals(List.of(), temporaries(work), Files.readString(work.resolve("child.out")));
            if (Files.isDirectory(logs)) {
                File[] written = logs.toFile().listFiles();
                for (File log : written == null ? new File[0] : written) {
                    // a log is there only when complete: it converts without error
                    assertTrue(org.scenes.internal.convert.SceneConverter.with(org.scenes.api.Grid.DEFAULT).build()
                            .convert(log.toPath(), scene -> { }).scenes() > 0, log.toString());
                }
            }
        }
    }

    /**
     * Sends the signal ({@code INT} is Ctrl-C's) to the child. A child that started with it
     * ignored (a background job of a non-interactive shell ignores SIGINT, and children inherit
     * that) cannot be stopped so: the test is skipped, saying why.
     */
    private static void signal(Process child, String signal) throws Exception {
        Path status = Path.of("/proc", String.valueOf(child.pid()), "status");
        if (Files.isReadable(status)) {
            long ignored = Files.readAllLines(status).stream().filter(l -> l.startsWith("SigIgn:"))
                    .mapToLong(l -> Long.parseUnsignedLong(l.substring(7).strip(), 16)).findFirst().orElse(0);
            int number = signal.equals("INT") ? 2 : 15;
            if ((ignored & 1L << (number - 1)) != 0) {
                child.destroyForcibly();
                Assumptions.abort("SIG" + signal + " is ignored in this process tree (started in the background"
                        + " by a non-interactive shell?), so the child cannot be stopped with it");
            }
        }
        Process kill = new ProcessBuilder("kill", "-" + signal, String.valueOf(child.pid())).start();
        assertTrue(kill.waitFor(10, TimeUnit.SECONDS) && kill.exitValue() == 0, "kill -" + signal);
    }

    /** The proxy, stopped as documented (SIGTERM, and SIGINT as Ctrl-C sends it), exits 0 (it exited 143 / 130). */
    @ParameterizedTest(name = "SIG{0}")
    @ValueSource(strings = {"TERM", "INT"})
    void theProxyStoppedBySignalExitsZeroAfterACleanShutdown(String signal) throws Exception {
        Path work = Files.createDirectories(dir.resolve("proxy-" + signal));
        Process child = start(work, "proxy", "--server", "127.0.0.1:6000", "--listen", "0", "--out", work.resolve("logs").toString());
        Path output = work.resolve("child.out");
        // bounded wait for the proxy to listen (its handlers are installed by then)
        for (int i = 0; i < 1200 && !Files.readString(output).contains("Ctrl-C to stop"); i++) {
            Thread.sleep(100);
        }
        assertTrue(Files.readString(output).contains("Ctrl-C to stop"), Files.readString(output));
        signal(child, signal);
        assertTrue(child.waitFor(60, TimeUnit.SECONDS), "the proxy stops");
        assertEquals(0, child.exitValue(), Files.readString(output));
        assertTrue(Files.readString(output).contains("messages logged"), "the summary is printed: " + Files.readString(output));
    }

    /**
     * Issue 31.6: the embedded server, stopped as documented while a player waits, exits 0 like
     * the proxy (it exited 143), its logs complete and named as rcssserver names them.
     */
    @ParameterizedTest(name = "SIG{0}")
    @ValueSource(strings = {"TERM", "INT"})
    void theServerStoppedBySignalExitsZeroWithItsLogsComplete(String signal) throws Exception {
        Path work = Files.createDirectories(dir.resolve("server-" + signal));
        Process child = start(work, "server", "--port", "0", "--record", work.resolve("logs").toString());
        Path output = work.resolve("child.out");
        // bounded wait until it serves (its handlers are installed by then)
        for (int i = 0; i < 1200 && !Files.readString(output).contains("Serving on UDP"); i++) {
            Thread.sleep(100);
        }
        String serving = Files.readString(output);
        assertTrue(serving.contains("Serving on UDP"), serving);
        int port = Integer.parseInt(serving.replaceAll("(?s).*Serving on UDP [^:]+:(\\d+).*", "$1"));
        try (DatagramSocket player = new DatagramSocket()) {
            player.setSoTimeout(10_000);
            byte[] init = "(init Teal (version 9))\0".getBytes(StandardCharsets.US_ASCII);
            player.send(new DatagramPacket(init, init.length, InetAddress.getLoopbackAddress(), port));
            // the server's first answer: the player is in (and then waits, getting sense_body)
            DatagramPacket answer = new DatagramPacket(new byte[8192], 8192);
            player.receive(answer);
            assertTrue(new String(answer.getData(), 0, answer.getLength(), StandardCharsets.US_ASCII).startsWith("(init l 1"));
            signal(child, signal);
            assertTrue(child.waitFor(60, TimeUnit.SECONDS), "the server stops");
        }
        assertEquals(0, child.exitValue(), Files.readString(output));
        try (var logs = Files.list(work.resolve("logs"))) {
            List<String> names = logs.map(f -> f.getFileName().toString()).sorted().toList();
            assertEquals(List.of("Teal_0-vs-null.rcg", "Teal_0-vs-null.rcl"), names);
        }
        assertTrue(Files.readString(work.resolve("logs/Teal_0-vs-null.rcl")).contains("Recv Teal_1: (init Teal (version 9))"));
    }
}
