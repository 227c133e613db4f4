package org.scenes.tests.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.scenes.api.Grid;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.internal.vision.Fading;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * {@code scenes convert GAME.rcg GAME.rcl --out-dir DIR} on a whole game: the simulator's 11 v 11
 * Krislet game of {@code cycles} cycles (seed 1, played once in the setup, recorded as rcssserver
 * records), every player's sees rebuilt and converted, 22 gzipped scene files written, on
 * {@code threads} threads. The JVM's heap is capped at 256 MB: conversion streams both logs.
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

    @Param({"2"})
    public int threads;

    private Path game;
    private Path rcg;
    private Path rcl;
    private Path out;

    @Setup
    public void play() throws IOException {
        game = Files.createTempDirectory("gamelog-bench");
        Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Teal", 11, Teachers.byName("krislet")),
                new GameSetup.Team("Amber", 11, Teachers.byName("krislet")), cycles, 1, game.resolve("players")))
                .recordTo(game);
        simulator.run(t -> { });
        for (Path file : simulator.recorded()) {
            if (file.toString().endsWith(".rcg")) {
                rcg = file;
            } else {
                rcl = file;
            }
        }
        out = game.resolve("scenes");
        Files.createDirectories(out);
        System.out.printf(Locale.ROOT, "%nGameLogBench: %s (%.1f MB) and %s (%.1f MB)%n", rcg.getFileName(),
                Files.size(rcg) / 1e6, rcl.getFileName(), Files.size(rcl) / 1e6);
    }

    @TearDown
    public void remove() throws IOException {
        try (Stream<Path> files = Files.walk(game)) {
            files.sorted(Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
        }
    }

    @Benchmark
    public long allPlayers() throws IOException {
        List<SceneFileWriter> writers = new ArrayList<>();
        try {
            GameLogConverter.Result result = new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY,
                    GameLogConverter.everyone(), threads).convert(rcg, rcl, observer -> {
                        SceneFileWriter writer = SceneFileWriter.create(out.resolve(observer.team() + "_"
                                + observer.uniformNumber() + ".json.gz"), SceneFileHeader.of(Grid.DEFAULT,
                                new SceneSource(rcg.getFileName().toString(), observer)));
                        writers.add(writer);
                        return writer::write;
                    });
            long scenes = 0;
            for (SceneFileWriter writer : writers) {
                writer.commit();
            }
            for (GameLogConverter.PlayerResult player : result.players()) {
                scenes += player.report().scenes();
            }
            System.out.printf(Locale.ROOT, "%n%d shows, %d players, %d scenes, heap used %.0f MB%n", result.frames(),
                    result.players().size(), scenes,
                    (Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory()) / 1e6);
            return scenes;
        } finally {
            for (SceneFileWriter writer : writers) {
                writer.close();
            }
        }
    }
}
