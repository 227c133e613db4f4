package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.app.bench.Bench;
import org.scenes.simulator.SyntheticScenes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/**
 * {@code scenes bench}: a short measurement of matching speed from the installed tool (the
 * measurement is the app layer's {@link Bench}; this command checks options and prints). The JMH
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

    @Parameters(arity = "0..*", paramLabel = "FILE",
            description = "Scene files (.json, .json.gz or .json.zst): the knowledge base; queries are spread over it.")
    List<Path> files;

    @Option(names = "--synthetic", paramLabel = "N", description = "Instead of files, a knowledge base of N synthetic scenes "
            + "(random moments of 11 v 11 Krislet games as the simulator sees them, seed " + Bench.SYNTHETIC_SEED
            + "), queried with other synthetic scenes.")
    Integer synthetic;

    @Option(names = "--synthetic-run", paramLabel = "N", defaultValue = "1", description = "With --synthetic: follow each"
            + " drawn observer for N consecutive cycles, its commands taking effect, so a scene's predecessor (what"
            + " memory configurations compare) is the same player a cycle earlier, as in a game (default ${DEFAULT-VALUE}:"
            + " independent moments).")
    int syntheticRun;

    @Option(names = "--metric", paramLabel = "NAME", description = "Metric to measure (repeatable; default: ball-goal"
            + " with and without its index, continuous greedy and optimal, cell, projection).")
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

    @Option(names = "--time", paramLabel = "SECONDS", defaultValue = "1",
            description = "Measuring time per metric, after as long again of warm-up (default ${DEFAULT-VALUE}).")
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
        List<Bench.Metric> chosen = new ArrayList<>();
        if (metrics == null) {
            chosen.addAll(Bench.defaultMetrics(registry));
        } else {
            metrics.forEach(name -> chosen.add(new Bench.Metric(name, name, PluginConfig.DEFAULT)));
        }
        List<Bench.Configured> configured = new ArrayList<>();
        if (configs != null) {
            for (Path file : configs) {
                configured.add(new Bench.Configured(file.getFileName().toString(), ConfigFiles.read(file)));
            }
        }
        Bench.Request request = new Bench.Request(noFiles ? List.of() : files, synthetic == null ? 0 : synthetic,
                syntheticRun, SyntheticScenes::generate, chosen, configured, queryFiles == null ? List.of() : queryFiles,
                queryCount, latency, seconds);
        Bench.Prepared prepared = Bench.prepare(request, registry, TerminalProgress.reporter());
        String made = synthetic == null ? "" : String.format(Locale.ROOT, " (generated in %.1f s%s)",
                prepared.generatedSeconds(), syntheticRun > 1 ? ", runs of " + syntheticRun + " cycles" : "");
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%d stored %sscenes%s, %d queries, one thread, k=1%n%-24s %18s", prepared.stored().size(),
                synthetic != null ? "synthetic " : "", made, prepared.queries().size(), "metric", "scenes per 100 ms");
        out.printf(Locale.ROOT, latency ? " %24s %24s%n" : "%n", "decision us p50 / p99", "CPU us p50 / p99");
        Bench.measure(prepared, registry, row -> {
            out.printf(Locale.ROOT, "%-24s %,18.0f", row.label(), row.scenesPer100ms());
            if (row.latency() != null) {
                out.printf(Locale.ROOT, " %24s %24s",
                        String.format(Locale.ROOT, "%.1f / %.1f", row.latency()[0], row.latency()[1]),
                        String.format(Locale.ROOT, "%.1f / %.1f", row.latency()[2], row.latency()[3]));
            }
            out.println();
            out.flush();
        });
        if (metrics == null && chosen.stream().anyMatch(m -> m.label().equals("ball-goal (index)"))) {
            out.println("ball-goal (index) visits few scenes: its figure is stored scenes over decision time.");
        }
        return ExitCodes.OK;
    }
}
