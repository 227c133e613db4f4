package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.scenes.agent.sim.SyntheticScenes;
import org.scenes.api.Grid;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginKind;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.validate.MatchConfig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/**
 * {@code scenes bench}: a short measurement of matching speed from the installed tool, one query
 * at a time scanned over the whole knowledge base on one thread, as the agent decides. The JMH
 * suite ({@code gradle :tests:jmh}) is the careful measurement; this is the quick look. With
 * {@code --synthetic N} the knowledge base is N generated scenes instead of files, so how speed
 * scales with size can be seen without recorded data.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Measure how many stored scenes each metric compares per 100 ms cycle and how long a decision takes (k=1, one thread).")
final class BenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    /** Seed of synthetic knowledge bases; queries use the next one, so they are other moments. */
    static final long SYNTHETIC_SEED = 1;

    @Parameters(arity = "0..*", paramLabel = "FILE", description = "Scene files (.json or .json.gz): the knowledge base; queries are spread over it.")
    List<Path> files;

    @Option(names = "--synthetic", paramLabel = "N", description = "Instead of files, a knowledge base of N synthetic scenes "
            + "(random moments of 11 v 11 Krislet games as the simulator sees them, seed " + SYNTHETIC_SEED
            + "), queried with other synthetic scenes.")
    Integer synthetic;

    @Option(names = "--synthetic-run", paramLabel = "N", defaultValue = "1", description = "With --synthetic: follow each"
            + " drawn observer for N consecutive cycles, its commands taking effect, so a scene's predecessor (what"
            + " memory configurations compare) is the same player a cycle earlier, as in a game (default ${DEFAULT-VALUE}:"
            + " independent moments).")
    int syntheticRun;

    @Option(names = "--metric", paramLabel = "NAME", description = "Metric to measure (repeatable; default: ball-goal with and without its index, continuous greedy and optimal, cell, projection).")
    List<String> metrics;

    @Option(names = "--config", paramLabel = "CONFIG.json", description = "Also measure this configuration (from scenes tune),"
            + " with its transforms applied to stored scenes and queries, at its k (repeatable).")
    List<Path> configs;

    @Option(names = "--queries", paramLabel = "FILE", description = "Scene files whose every scene is a query"
            + " (held out: not stored), with each configuration's transforms; default: 64 stored scenes spread over the knowledge base.")
    List<Path> queryFiles;

    @Option(names = "--query-count", paramLabel = "N", defaultValue = "64", description = "Queries without --queries:"
            + " this many synthetic ones, or stored scenes spread over the knowledge base (default ${DEFAULT-VALUE}).")
    int queryCount;

    @Option(names = "--latency", description = "Add each decision's wall-clock and thread CPU time, p50 and p99 in"
            + " microseconds (a neighbour search; CPU time leaves out the waits of a busy machine).")
    boolean latency;

    @Option(names = "--time", paramLabel = "SECONDS", defaultValue = "1", description = "Measuring time per metric, after as long again of warm-up (default ${DEFAULT-VALUE}).")
    double seconds;

    @Override
    public Integer call() {
        if (!(seconds > 0)) {
            throw new UsageException("--time must be positive, not " + seconds);
        }
        boolean noFiles = files == null || files.isEmpty();
        if (synthetic == null && noFiles) {
            throw new UsageException("give scene files or --synthetic N");
        }
        if (synthetic != null && !noFiles) {
            throw new UsageException("--synthetic measures generated scenes; give it without scene files");
        }
        if (synthetic != null && queryFiles != null) {
            throw new UsageException("--queries needs scene files as knowledge base, not --synthetic");
        }
        if (queryCount < 1) {
            throw new UsageException("--query-count must be at least 1, not " + queryCount);
        }
        if (synthetic != null && synthetic < 1) {
            throw new UsageException("--synthetic needs at least 1 scene, not " + synthetic);
        }
        if (synthetic != null) {
            Limits.heapFor("--synthetic", synthetic, Limits.BYTES_PER_SCENE);
        }
        if (syntheticRun < 1) {
            throw new UsageException("--synthetic-run must be at least 1, not " + syntheticRun);
        }
        if (syntheticRun > 1 && synthetic == null) {
            throw new UsageException("--synthetic-run follows synthetic observers; give it with --synthetic N");
        }
        PluginRegistry registry = top.global.registry();
        List<Measured> chosen = new ArrayList<>();
        if (metrics == null) {
            List<String> available = registry.names(PluginKind.METRIC);
            if (available.contains("ball-goal")) {
                chosen.add(new Measured("ball-goal (index)", "ball-goal", PluginConfig.DEFAULT));
                chosen.add(new Measured("ball-goal (scan)", "ball-goal", PluginConfig.DEFAULT.withOptions(Map.of("index", "false"))));
            }
            for (String name : List.of("continuous", "cell", "projection")) {
                if (available.contains(name)) {
                    chosen.add(new Measured(name, name, PluginConfig.DEFAULT));
                }
            }
            if (available.contains("continuous")) {
                chosen.add(new Measured("continuous (optimal)", "continuous", PluginConfig.DEFAULT.withOptions(Map.of("matching", "optimal"))));
            }
        } else {
            metrics.forEach(name -> chosen.add(new Measured(name, name, PluginConfig.DEFAULT)));
        }
        List<MatchConfig> configured = new ArrayList<>();
        if (configs != null) {
            for (Path file : configs) {
                MatchConfig config = ConfigFiles.read(file);
                config.check(registry);
                configured.add(config);
            }
        }
        KnowledgeBase knowledge;
        List<Scene> queries = new ArrayList<>();
        String made = "";
        if (synthetic != null) {
            long start = System.nanoTime();
            knowledge = generate(synthetic, syntheticRun);
            made = String.format(Locale.ROOT, " (generated in %.1f s%s)", (System.nanoTime() - start) / 1e9,
                    syntheticRun > 1 ? ", runs of " + syntheticRun + " cycles" : "");
            SyntheticScenes.generate(SYNTHETIC_SEED + 1, queryCount, syntheticRun, Grid.DEFAULT, queries::add);
        } else {
            knowledge = KnowledgeBase.load(files, List::of);
            queries = queries(knowledge, List::of);
        }
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%d stored %sscenes%s, %d queries, one thread, k=1%n%-24s %18s", knowledge.size(),
                synthetic != null ? "synthetic " : "", made, queries.size(), "metric", "scenes per 100 ms");
        out.printf(Locale.ROOT, latency ? " %24s %24s%n" : "%n", "decision us p50 / p99", "CPU us p50 / p99");
        for (Measured measured : chosen) {
            registry.check(PluginKind.METRIC, measured.name(), measured.config());
            Recognizer recognizer = new Recognizer(knowledge, () -> registry.metric(measured.name(), measured.config()), 1);
            row(out, measured.label(), recognizer, queries, knowledge.size());
        }
        for (int c = 0; c < configured.size(); c++) {
            MatchConfig config = configured.get(c);
            // the configuration's transforms (memory) on the stored scenes and the queries alike
            KnowledgeBase transformed;
            List<Scene> transformedQueries = new ArrayList<>();
            if (synthetic != null) {
                transformed = KnowledgeBase.of(Grid.DEFAULT, KnowledgeBase.transform(knowledge.scenes(),
                        config.transformFactory(registry).get()));
                transformedQueries = KnowledgeBase.transform(queries, config.transformFactory(registry).get());
            } else {
                transformed = KnowledgeBase.load(files, config.transformFactory(registry));
                transformedQueries = queries(transformed, config.transformFactory(registry));
            }
            Recognizer recognizer = config.recognizer(transformed, registry, config.k());
            row(out, configs.get(c).getFileName().toString(), recognizer, transformedQueries, transformed.size());
        }
        if (metrics == null && chosen.stream().anyMatch(m -> m.label().equals("ball-goal (index)"))) {
            out.println("ball-goal (index) visits few scenes: its figure is stored scenes over decision time.");
        }
        return ExitCodes.OK;
    }

    /** Every scene of the --queries files (transformed as the knowledge base), or stored scenes spread over it. */
    private List<Scene> queries(KnowledgeBase knowledge, java.util.function.Supplier<List<org.scenes.api.SceneTransform>> transforms) {
        if (queryFiles != null) {
            List<Scene> all = new ArrayList<>();
            for (Path file : queryFiles) {
                all.addAll(KnowledgeBase.transform(org.scenes.internal.scene.SceneFileReader.read(file).scenes(), transforms.get()));
            }
            return all;
        }
        List<Scene> spread = new ArrayList<>();
        int count = Math.min(queryCount, knowledge.size());
        for (int i = 0; i < count; i++) {
            spread.add(knowledge.scene((int) ((long) i * knowledge.size() / count)));
        }
        return spread;
    }

    /** One measured row: throughput, then the wall and CPU time of each decision. */
    private void row(PrintWriter out, String label, Recognizer recognizer, List<Scene> queries, int stored) {
        scans(recognizer, queries, seconds); // warm-up
        double perSecond = scans(recognizer, queries, seconds) * stored;
        out.printf(Locale.ROOT, "%-24s %,18.0f", label, perSecond / 10);
        if (latency) {
            long[][] times = decisions(recognizer, queries, seconds);
            out.printf(Locale.ROOT, " %24s %24s",
                    String.format(Locale.ROOT, "%.1f / %.1f", percentile(times[0], 0.5), percentile(times[0], 0.99)),
                    String.format(Locale.ROOT, "%.1f / %.1f", percentile(times[1], 0.5), percentile(times[1], 0.99)));
        }
        out.println();
        out.flush();
    }

    /**
     * Wall and thread CPU nanoseconds of each of at least one pass of decisions over the queries
     * (longer while {@code seconds} last): CPU time leaves out the waits of a busy machine.
     */
    private static long[][] decisions(Recognizer recognizer, List<Scene> queries, double seconds) {
        java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
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
    private static double percentile(long[] nanos, double q) {
        long[] sorted = nanos.clone();
        java.util.Arrays.sort(sorted);
        int rank = (int) Math.ceil(q * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, rank))] / 1000.0;
    }

    /** A row of the table: what it is called and the metric with its options. */
    private record Measured(String label, String name, PluginConfig config) {
    }

    /** Synthetic scenes streamed into a knowledge base, with a progress bar on a terminal. */
    private static KnowledgeBase generate(int count, int run) {
        KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
        try (ProgressBar bar = System.console() == null || count < 50_000 ? null
                : new ProgressBarBuilder().setTaskName("Generating").setInitialMax(count).setUnit(" scenes", 1)
                        .setConsumer(new ConsoleProgressBarConsumer(System.err)).clearDisplayOnFinish().build()) {
            SyntheticScenes.generate(SYNTHETIC_SEED, count, run, Grid.DEFAULT, scene -> {
                builder.add(scene);
                if (bar != null) {
                    bar.step();
                }
            });
        }
        return builder.build();
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
