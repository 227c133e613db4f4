package org.scenes.tests.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;
import org.scenes.api.Grid;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.GameSceneFiles;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandSource;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.inference.InferredCommandLog;
import org.scenes.internal.vision.Fading;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * {@code scenes convert GAME.rcg --out-dir DIR} on a whole game, by the command's own code
 * ({@link GameSceneFiles}): every player's sees rebuilt and converted with its world model (the
 * default), 22 gzipped scene files written, on {@code threads} threads; the commands from the
 * command log ({@code commands=rcl}) or inferred from the game log alone ({@code infer}). The game
 * is the simulator's 11 v 11 Krislet game of {@code cycles} cycles (seed 1, played once in the
 * setup, recorded as rcssserver records), or the game log named by {@code game} (its command log
 * beside it), e.g. one of the real HELIOS games. The JVM's heap is capped at 256 MB: conversion
 * streams both logs. One operation is a whole game; {@code -prof gc} gives its allocation.
 *
 * <p>The other benchmarks split the cost: {@link #zstdFiles} writes them zstd-compressed,
 * {@link #plainJson} the same scene files without compression, {@link #noFiles} hands the scenes to a blackhole (rebuilding, parsing, world models,
 * pairing, and the inference for {@code infer}), {@link #readGameLog} only reads the game log's
 * shows. Each operation prints the process's CPU time it took (JIT and GC threads included),
 * the figure to read on a machine whose cores are shared.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 1)
@Measurement(iterations = 3)
@Fork(value = 1, jvmArgsAppend = "-Xmx256m")
public class GameLogBench {
    @Param({"6000"})
    public int cycles;

    /** One thread by default: the operation's time is then its CPU time on a free core. */
    @Param({"1"})
    public int threads;

    @Param({"true"})
    public boolean world;

    @Param({"rcl", "infer"})
    public String commands;

    /** A game log to convert instead of the simulated game; empty for the simulated one. */
    @Param({""})
    public String game;

    private Path directory;
    private Path rcg;
    private Path rcl;
    private Path out;
    private long cpuAtStart;

    @Setup
    public void play() throws IOException {
        directory = Files.createTempDirectory("gamelog-bench");
        if (game.isEmpty()) {
            Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Teal", 11, Teachers.byName("krislet")),
                    new GameSetup.Team("Amber", 11, Teachers.byName("krislet")), cycles, 1,
                    directory.resolve("players"))).recordTo(directory);
            simulator.run(t -> { });
            for (Path file : simulator.recorded()) {
                if (file.toString().endsWith(".rcg")) {
                    rcg = file;
                } else {
                    rcl = file;
                }
            }
        } else {
            rcg = Path.of(game);
            rcl = GameLogs.commandLogBeside(rcg);
        }
        out = directory.resolve("scenes");
        Files.createDirectories(out);
        System.out.printf(Locale.ROOT, "%nGameLogBench: %s (%.1f MB) and %s (%.1f MB)%n", rcg.getFileName(),
                Files.size(rcg) / 1e6, rcl.getFileName(), Files.size(rcl) / 1e6);
    }

    @Setup(Level.Invocation)
    public void startClock() {
        cpuAtStart = cpuNanos();
    }

    @TearDown(Level.Invocation)
    public void printClock() {
        System.out.printf(Locale.ROOT, "%nprocess CPU %.2f s%n", (cpuNanos() - cpuAtStart) / 1e9);
    }

    private static long cpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    @TearDown
    public void remove() throws IOException {
        try (Stream<Path> files = Files.walk(directory)) {
            files.sorted(Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
        }
    }

    @Benchmark
    public long allPlayers() throws IOException {
        return write(".json.gz");
    }

    /** As {@code scenes convert --compression zstd}. */
    @Benchmark
    public long zstdFiles() throws IOException {
        return write(".json.zst");
    }

    @Benchmark
    public long plainJson() throws IOException {
        return write(".json");
    }

    @Benchmark
    public long noFiles(Blackhole scenes) throws IOException {
        GameLogs logs = logs();
        try (CommandSource source = logs.inferred() ? InferredCommandLog.of(rcg) : CommandLogReader.open(rcl)) {
            return converter().convert(rcg, source, observer -> scenes::consume).frames();
        }
    }

    @Benchmark
    public long readGameLog() throws IOException {
        long[] players = new long[1];
        GameLogReader.forEach(rcg, frame -> players[0] += frame.players().size());
        return players[0];
    }

    private GameLogConverter converter() {
        return new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.dice(1), GameLogConverter.everyone(), threads)
                .world(world);
    }

    private GameLogs logs() {
        return new GameLogs(rcg, commands.equals("infer") ? null : rcl);
    }

    private long write(String suffix) throws IOException {
        GameSceneFiles.Written written = GameSceneFiles.write(converter(), Grid.DEFAULT, logs(),
                key -> out.resolve(key + suffix));
        System.out.printf(Locale.ROOT, "%n%d shows, %d players, %d scenes, heap used %.0f MB",
                written.result().frames(), written.result().players().size(), written.scenes(),
                (Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory()) / 1e6);
        return written.scenes();
    }
}
