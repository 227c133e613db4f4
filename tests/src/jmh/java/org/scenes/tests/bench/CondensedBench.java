package org.scenes.tests.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
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
import org.openjdk.jmh.annotations.Warmup;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.coverage.Condenser;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * A {@code ball-goal} decision ({@link Recognizer#nearest}, k = 1) on the whole of the recorded
 * Krislet game {@code classic-game1} against the same game condensed ({@code scenes condense}:
 * {@code condensed} keeps 2081 of 24438 scenes, {@code edited} edits with k = 3 first and keeps
 * 137), queried with every scene of {@code classic-game2} in turn: the scenes held out in
 * docs/extensions.md. Average time per decision.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class CondensedBench {
    @Param({"full", "condensed", "edited"})
    public String knowledge;

    private Recognizer recognizer;
    private List<Scene> queries;
    private int next;

    @Setup
    public void build() {
        long start = System.nanoTime();
        List<Scene> stored = game("classic-game1");
        queries = game("classic-game2");
        java.util.function.Supplier<SceneMetric> metric = BenchSets.metric("ball-goal-index");
        if (!knowledge.equals("full")) {
            stored = new Condenser(metric, knowledge.equals("edited") ? 3 : 0).condense(Grid.DEFAULT, stored).scenes();
        }
        recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), metric, 1);
        BenchSets.report(knowledge + ": " + stored.size() + " stored scenes, " + queries.size() + " queries", start);
    }

    /** Every player's scenes of one recorded game, one file after the other. */
    private static List<Scene> game(String game) {
        Path folder = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet", game);
        List<Scene> scenes = new ArrayList<>();
        try (DirectoryStream<Path> logs = Files.newDirectoryStream(folder, "*.lsf.gz")) {
            List<Path> sorted = new ArrayList<>();
            logs.forEach(sorted::add);
            sorted.sort(null);
            for (Path log : sorted) {
                SceneConverter.with(Grid.DEFAULT).build().convert(log, scenes::add);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return scenes;
    }

    @Benchmark
    public List<Neighbour> decide() {
        next = (next + 1) % queries.size();
        return recognizer.nearest(queries.get(next));
    }
}
