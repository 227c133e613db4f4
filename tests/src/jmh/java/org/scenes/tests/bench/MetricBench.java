package org.scenes.tests.bench;

import java.io.IOException;
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
import org.openjdk.jmh.infra.Blackhole;
import org.scenes.api.Grid;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * k-NN search with a metric, as validation and the live agent run it: one operation finds the
 * nearest stored scene for each of 200 queries (Krislet, classic game 1: Carleton_2's scenes
 * against the knowledge base of Carleton_1's). {@code metric} names the plugin; {@code
 * script-ball-goal} is the shipped example script {@code examples/scripts/ball-goal.groovy},
 * compiled as {@code --metric script:...} compiles it, next to the built-in Java
 * {@code ball-goal} it is equivalent to. Throughput in queries per second = 200 / score.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 3)
@Measurement(iterations = 5, time = 3)
@Fork(value = 1, jvmArgsAppend = "-Xmx1g")
public class MetricBench {
    private static final int QUERIES = 200;

    @Param({"ball-goal", "script-ball-goal"})
    public String metric;

    private Recognizer recognizer;
    private List<Scene> queries;

    @Setup
    public void load() throws IOException {
        Path game = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet", "classic-game1");
        List<Scene> stored = scenes(game.resolve("Carleton_1.lsf.gz"));
        List<Scene> test = scenes(game.resolve("Carleton_2.lsf.gz"));
        queries = new ArrayList<>();
        for (int i = 0; i < QUERIES; i++) {
            queries.add(test.get(i * test.size() / QUERIES));
        }
        String spec = metric.equals("script-ball-goal")
                ? "script:" + Path.of(System.getProperty("scenes.examples", "../examples/scripts"), "ball-goal.groovy")
                : metric;
        PluginRegistry registry = PluginRegistry.load();
        recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), () -> registry.metric(spec, PluginConfig.DEFAULT), 1);
        System.out.printf("%nMetricBench %s: %d stored scenes, %d queries per operation%n", spec, stored.size(), QUERIES);
    }

    private static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build().convert(log, scenes::add);
        return scenes;
    }

    @Benchmark
    public void nearest(Blackhole sink) {
        for (Scene query : queries) {
            sink.consume(recognizer.nearest(query));
        }
    }
}
