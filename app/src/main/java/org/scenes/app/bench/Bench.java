package org.scenes.app.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.scenes.api.Grid;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginKind;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.app.Progress;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.validate.MatchConfig;

/**
 * {@code scenes bench}: a short measurement of matching speed, one query at a time scanned over the
 * whole knowledge base on one thread, as the agent decides: stored scenes compared per 100 ms cycle,
 * and optionally each decision's wall-clock and CPU time. The knowledge base is scene files or
 * synthetic scenes from a generator the caller supplies.
 */
public final class Bench {
    /** Seed of synthetic knowledge bases; queries use the next one, so they are other moments. */
    public static final long SYNTHETIC_SEED = 1;
    /** Generating fewer synthetic scenes reports no progress. */
    private static final int LARGE_SYNTHETIC = 50_000;

    /** Makes synthetic scenes: {@code count} from {@code seed}, each observer followed for {@code run} cycles. */
    @FunctionalInterface
    public interface Generator {
        void generate(long seed, int count, int run, Grid grid, Consumer<Scene> sink);
    }

    /** A metric measured: the row's label, the metric's name and its options. */
    public record Metric(String label, String name, PluginConfig config) {
    }

    /** A configuration measured (from {@code scenes tune}), with its transforms and k. */
    public record Configured(String label, MatchConfig config) {
    }

    /**
     * What to measure.
     *
     * @param files the knowledge base's scene files; empty with {@code synthetic}
     * @param synthetic synthetic scenes stored instead of files, or 0
     * @param syntheticRun cycles each synthetic observer is followed
     * @param generator what makes synthetic scenes; may be null without {@code synthetic}
     * @param metrics the metrics measured, in order
     * @param configured the configurations measured after them
     * @param queryFiles files whose every scene is a query (held out), or empty
     * @param queryCount queries otherwise: synthetic ones, or stored scenes spread over the knowledge base
     * @param latency also time each decision
     * @param seconds measuring time per row, after as long again of warm-up
     */
    public record Request(List<Path> files, int synthetic, int syntheticRun, Generator generator, List<Metric> metrics,
                          List<Configured> configured, List<Path> queryFiles, int queryCount, boolean latency,
                          double seconds) {
        public Request {
            files = List.copyOf(files);
            metrics = List.copyOf(metrics);
            configured = List.copyOf(configured);
            queryFiles = List.copyOf(queryFiles);
        }
    }

    /**
     * One measured row.
     *
     * @param label the metric's or configuration's label
     * @param scenesPer100ms stored scenes compared per 100 ms
     * @param latency wall p50, wall p99, CPU p50, CPU p99 of a decision in microseconds; null unless asked
     */
    public record Row(String label, double scenesPer100ms, double[] latency) {
    }

    /**
     * A knowledge base and queries, ready to measure.
     *
     * @param stored the stored scenes
     * @param queries the queries
     * @param generatedSeconds seconds spent generating synthetic scenes, 0 for files
     */
    public record Prepared(Request request, KnowledgeBase stored, List<Scene> queries, double generatedSeconds) {
    }

    private Bench() {
    }

    /** The metrics measured by default: ball-goal with and without its index, continuous greedy and optimal, cell, projection. */
    public static List<Metric> defaultMetrics(PluginRegistry registry) {
        List<String> available = registry.names(PluginKind.METRIC);
        List<Metric> chosen = new ArrayList<>();
        if (available.contains("ball-goal")) {
            chosen.add(new Metric("ball-goal (index)", "ball-goal", PluginConfig.DEFAULT));
            chosen.add(new Metric("ball-goal (scan)", "ball-goal", PluginConfig.DEFAULT.withOptions(Map.of("index", "false"))));
        }
        for (String name : List.of("continuous", "cell", "projection")) {
            if (available.contains(name)) {
                chosen.add(new Metric(name, name, PluginConfig.DEFAULT));
            }
        }
        if (available.contains("continuous")) {
            chosen.add(new Metric("continuous (optimal)", "continuous", PluginConfig.DEFAULT.withOptions(Map.of("matching", "optimal"))));
        }
        return chosen;
    }

    /** Builds the knowledge base (reporting the generation of a large synthetic one) and chooses the queries. */
    public static Prepared prepare(Request request, PluginRegistry registry, Progress progress) {
        for (Configured configured : request.configured()) {
            configured.config().check(registry);
        }
        if (request.synthetic() > 0) {
            long start = System.nanoTime();
            KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
            Progress generating = request.synthetic() < LARGE_SYNTHETIC ? Progress.NONE : progress;
            generating.begin("Generating", request.synthetic());
            try {
                request.generator().generate(SYNTHETIC_SEED, request.synthetic(), request.syntheticRun(), Grid.DEFAULT,
                        scene -> {
                            builder.add(scene);
                            generating.step();
                        });
            } finally {
                generating.end();
            }
            KnowledgeBase stored = builder.build();
            double seconds = (System.nanoTime() - start) / 1e9;
            List<Scene> queries = new ArrayList<>();
            request.generator().generate(SYNTHETIC_SEED + 1, request.queryCount(), request.syntheticRun(), Grid.DEFAULT,
                    queries::add);
            return new Prepared(request, stored, queries, seconds);
        }
        KnowledgeBase stored = KnowledgeBase.load(request.files(), List::of);
        return new Prepared(request, stored, queries(request, stored, List::of), 0);
    }

    /** Measures every metric, then every configuration, each row told as soon as it is measured. */
    public static void measure(Prepared prepared, PluginRegistry registry, Consumer<Row> rows) {
        Request request = prepared.request();
        KnowledgeBase knowledge = prepared.stored();
        for (Metric metric : request.metrics()) {
            registry.check(PluginKind.METRIC, metric.name(), metric.config());
            Recognizer recognizer = new Recognizer(knowledge, () -> registry.metric(metric.name(), metric.config()), 1);
            rows.accept(row(request, metric.label(), recognizer, prepared.queries(), knowledge.size()));
        }
        for (Configured configured : request.configured()) {
            MatchConfig config = configured.config();
            // the configuration's transforms (memory) on the stored scenes and the queries alike
            KnowledgeBase transformed;
            List<Scene> transformedQueries;
            if (request.synthetic() > 0) {
                transformed = KnowledgeBase.of(Grid.DEFAULT, KnowledgeBase.transform(knowledge.scenes(),
                        config.transformFactory(registry).get()));
                transformedQueries = KnowledgeBase.transform(prepared.queries(), config.transformFactory(registry).get());
            } else {
                transformed = KnowledgeBase.load(request.files(), config.transformFactory(registry));
                transformedQueries = queries(request, transformed, config.transformFactory(registry));
            }
            Recognizer recognizer = config.recognizer(transformed, registry, config.k());
            rows.accept(row(request, configured.label(), recognizer, transformedQueries, transformed.size()));
        }
    }

    /** Every scene of the query files (transformed as the knowledge base), or stored scenes spread over it. */
    private static List<Scene> queries(Request request, KnowledgeBase knowledge, Supplier<List<SceneTransform>> transforms) {
        if (!request.queryFiles().isEmpty()) {
            List<Scene> all = new ArrayList<>();
            for (Path file : request.queryFiles()) {
                all.addAll(KnowledgeBase.transform(SceneFileReader.read(file).scenes(), transforms.get()));
            }
            return all;
        }
        List<Scene> spread = new ArrayList<>();
        int count = Math.min(request.queryCount(), knowledge.size());
        for (int i = 0; i < count; i++) {
            spread.add(knowledge.scene((int) ((long) i * knowledge.size() / count)));
        }
        return spread;
    }

    /** One measured row: throughput, then the wall and CPU time of each decision. */
    private static Row row(Request request, String label, Recognizer recognizer, List<Scene> queries, int stored) {
        scans(recognizer, queries, request.seconds()); // warm-up
        double perSecond = scans(recognizer, queries, request.seconds()) * stored;
        double[] latency = null;
        if (request.latency()) {
            long[][] times = decisions(recognizer, queries, request.seconds());
            latency = new double[] {percentile(times[0], 0.5), percentile(times[0], 0.99), percentile(times[1], 0.5),
                    percentile(times[1], 0.99)};
        }
        return new Row(label, perSecond / 10, latency);
    }

    /**
     * Wall and thread CPU nanoseconds of each of at least one pass of decisions over the queries
     * (longer while {@code seconds} last): CPU time leaves out the waits of a busy machine.
     */
    private static long[][] decisions(Recognizer recognizer, List<Scene> queries, double seconds) {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        List<long[]> samples = new ArrayList<>();
        long end = System.nanoTime() + (long) (seconds * 1e9);
        int done = 0;
        while (done < queries.size() || System.nanoTime() < end && done < 2_000_000) {
            Scene query = queries.get(done % queries.size());
            long cpu = threads.getCurrentThreadCpuTime();
            long wall = System.nanoTime();
            recognizer.nearest(query);
            samples.add(new long[] {System.nanoTime() - wall, threads.getCurrentThreadCpuTime() - cpu});
            done++;
        }
        long[][] times = new long[2][samples.size()];
        for (int i = 0; i < samples.size(); i++) {
            times[0][i] = samples.get(i)[0];
            times[1][i] = samples.get(i)[1];
        }
        return times;
    }

    /** The q-quantile (nearest rank) in microseconds. */
    static double percentile(long[] nanos, double q) {
        long[] sorted = nanos.clone();
        Arrays.sort(sorted);
        int rank = (int) Math.ceil(q * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, rank))] / 1000.0;
    }

    /** Queries answered per second, each scanning the whole knowledge base. */
    private static double scans(Recognizer recognizer, List<Scene> queries, double seconds) {
        long start = System.nanoTime();
        long end = start + (long) (seconds * 1e9);
        long done = 0;
        long now;
        do {
            recognizer.nearest(queries.get((int) (done % queries.size())));
            done++;
            now = System.nanoTime();
        } while (now < end);
        return done / ((now - start) / 1e9);
    }
}
