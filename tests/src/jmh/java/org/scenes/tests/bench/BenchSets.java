package org.scenes.tests.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import org.scenes.api.Grid;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.simulator.SyntheticScenes;

/**
 * The scene sets of the scaling benchmarks: synthetic knowledge bases of any size (seed 1) with
 * synthetic queries (seed 2, other moments than the stored ones), and the recorded Krislet game 1
 * (every player but Carleton_2 stored, Carleton_2's scenes as queries). Setups print how long
 * building took and the heap then in use, so reports can quote them.
 */
final class BenchSets {
    static final long KNOWLEDGE_SEED = 1;
    static final long QUERY_SEED = 2;
    static final int QUERIES = 256;
    private static final String[] KRISLET_STORED = {"Carleton_1", "Carleton_3", "Carleton_4", "Carleton_5",
        "University_1", "University_2", "University_3", "University_4", "University_5"};

    private BenchSets() {
    }

    /** Metric options given to a benchmark as {@code KEY=VALUE} pairs, blank ones skipped; a later key wins. */
    static Map<String, String> options(String... pairs) {
        Map<String, String> options = new LinkedHashMap<>();
        for (String pair : pairs) {
            if (!pair.isBlank()) {
                String[] keyValue = pair.split("=", 2);
                options.put(keyValue[0].trim(), keyValue[1].trim());
            }
        }
        return options;
    }

    /** {@code size} synthetic scenes streamed into a knowledge base, never all held as objects. */
    static KnowledgeBase synthetic(int size) {
        return synthetic(size, false);
    }

    /** As {@link #synthetic(int)}; with {@code remember}, each scene remembers the one generated before it. */
    static KnowledgeBase synthetic(int size, boolean remember) {
        long start = System.nanoTime();
        KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
        java.util.function.Consumer<Scene> add = remember ? remembering(builder::add) : builder::add;
        SyntheticScenes.generate(KNOWLEDGE_SEED, size, Grid.DEFAULT, add);
        KnowledgeBase knowledge = builder.build();
        report("generated " + size + " synthetic scenes into the knowledge base", start);
        return knowledge;
    }

    static List<Scene> syntheticQueries() {
        return syntheticQueries(false);
    }

    static List<Scene> syntheticQueries(boolean remember) {
        List<Scene> queries = new ArrayList<>(QUERIES);
        java.util.function.Consumer<Scene> add = remember ? remembering(queries::add) : queries::add;
        SyntheticScenes.generate(QUERY_SEED, QUERIES, Grid.DEFAULT, add);
        return queries;
    }

    /** What the memory transform does to one file: each scene remembers the one before it. */
    static java.util.function.Consumer<Scene> remembering(java.util.function.Consumer<Scene> sink) {
        Scene[] last = new Scene[1];
        return scene -> {
            Scene remembered = last[0] == null ? scene : scene.withPrevious(last[0]);
            last[0] = scene;
            sink.accept(remembered);
        };
    }

    /** Whether a benchmark metric name (see {@link #metric}) needs the memory transform. */
    static boolean remembers(String metric) {
        return metric.startsWith("tuned");
    }

    /** Game 1 of the shared Krislet data without Carleton_2 (about 22,000 scenes). */
    static KnowledgeBase krislet() {
        return krislet(false);
    }

    /** As {@link #krislet()}; with {@code remember}, each player's scenes remember their previous one. */
    static KnowledgeBase krislet(boolean remember) {
        long start = System.nanoTime();
        KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
        for (String player : KRISLET_STORED) {
            java.util.function.Consumer<Scene> add = remember ? remembering(builder::add) : builder::add;
            convert(player, add::accept);
        }
        KnowledgeBase knowledge = builder.build();
        report("converted " + knowledge.size() + " Krislet game 1 scenes into the knowledge base", start);
        return knowledge;
    }

    /** {@value #QUERIES} of Carleton_2's scenes, spread evenly over its game. */
    static List<Scene> krisletQueries() {
        return krisletQueries(false);
    }

    static List<Scene> krisletQueries(boolean remember) {
        List<Scene> all = new ArrayList<>();
        java.util.function.Consumer<Scene> add = remember ? remembering(all::add) : all::add;
        convert("Carleton_2", add::accept);
        List<Scene> queries = new ArrayList<>(QUERIES);
        for (int i = 0; i < QUERIES; i++) {
            queries.add(all.get(i * all.size() / QUERIES));
        }
        return queries;
    }

    private static void convert(String player, SceneConverter.SceneSink sink) {
        Path log = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet", "classic-game1",
                player + ".lsf.gz");
        try {
            SceneConverter.with(Grid.DEFAULT).build().convert(log, sink);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * A fresh-metric supplier for a benchmark name: a metric plugin's name, {@code continuous-optimal}
     * ({@code continuous} with {@code matching=optimal}), {@code script-ball-goal} (the shipped
     * example script), and as in {@link MatchBench} {@code ball-goal} is its packed scan
     * ({@code index=false}) and {@code ball-goal-index} its exact index (the plugin's default);
     * {@code tuned} is the tuned Krislet configuration of the README ({@code continuous}, polar,
     * ball and goals, memory of the previous action: its low-dimensional index) and
     * {@code tuned-scan} the same scanning every scene ({@code index=false}), {@code tuned-nearest}
     * the same with the nearest teammate and opponent weighed too ({@code nearest-players}); all
     * need the memory transform ({@link #remembers}).
     */
    static Supplier<SceneMetric> metric(String name) {
        PluginRegistry registry = PluginRegistry.load();
        String spec = switch (name) {
            case "script-ball-goal" -> "script:" + Path.of(System.getProperty("scenes.examples", "../examples/scripts"), "ball-goal.groovy");
            case "continuous-optimal" -> "continuous";
            case "ball-goal-index" -> "ball-goal";
            case "tuned", "tuned-scan", "tuned-nearest" -> "continuous";
            default -> name;
        };
        PluginConfig config = switch (name) {
            case "continuous-optimal" -> PluginConfig.DEFAULT.withOptions(Map.of("matching", "optimal"));
            case "ball-goal" -> PluginConfig.DEFAULT.withOptions(Map.of("index", "false"));
            case "tuned", "tuned-scan", "tuned-nearest" -> PluginConfig.DEFAULT
                    .withObjectWeights(ObjectWeights.parse(name.equals("tuned-nearest")
                            ? "ball=1,goal=0.05,teammates=0.05,opponents=0.05" : "ball=1,goal=0.05"))
                    .withOptions(Map.of("space", "polar", "log-distance", "true", "distance-weight", "30",
                            "direction-weight", "10", "row-weight", "1000", "penalty", "20000", "penalty-scale", "10000",
                            "memory-action", "100", "index", Boolean.toString(!name.equals("tuned-scan")),
                            "nearest-players", Boolean.toString(name.equals("tuned-nearest"))));
            default -> PluginConfig.DEFAULT;
        };
        return () -> registry.metric(spec, config);
    }

    /** A recognizer, reporting how long packing the knowledge base for the metric took. */
    static Recognizer recognizer(KnowledgeBase knowledge, String metric, int k) {
        long start = System.nanoTime();
        Recognizer recognizer = new Recognizer(knowledge, metric(metric), k);
        report("recognizer for " + metric + " (k=" + k + ") built", start);
        return recognizer;
    }

    /** One setup line: what was done, in how long, and the heap in use after a collection. */
    static void report(String what, long startNanos) {
        double seconds = (System.nanoTime() - startNanos) / 1e9;
        System.gc();
        Runtime runtime = Runtime.getRuntime();
        long usedMb = (runtime.totalMemory() - runtime.freeMemory()) >> 20;
        System.out.printf(Locale.ROOT, "%n[setup] %s in %.1f s; heap used %d MB of max %d MB%n", what, seconds, usedMb,
                runtime.maxMemory() >> 20);
    }
}
