package org.scenes.tests.bench;

import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
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
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * The time of one decision of the imitating agent: the k nearest stored scenes of a query
 * ({@link Recognizer#nearest}) and the selector's choice among them ({@code first-valid} for
 * k = 1, {@code vote} for k = 5 and 15, the selectors plugin), sampled per call so p50 and p99
 * are reported. Knowledge bases ({@code knowledge}): {@code krislet}, the recorded Krislet game 1
 * without Carleton_2 (Carleton_2's scenes are the queries), or that many synthetic scenes. Metrics
 * named as in {@link BenchSets#metric}: {@code ball-goal-index} is what the agent uses,
 * {@code ball-goal} the packed scan without the index, {@code tuned} the tuned Krislet
 * configuration through its low-dimensional index, {@code tuned-nearest} it with the nearest teammate and
 * opponent too, and {@code tuned-scan} the same scanning every scene
 * ({@link BenchSets#synthetic}, synthetic queries). Each fork builds its knowledge base once
 * (printed as a {@code [setup]} line with the heap in use).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
// room for packing 10^6 scenes for continuous (see ScaleBench)
@Fork(value = 1, jvmArgsAppend = "-Xmx6g")
public class DecisionBench {
    @Param({"krislet", "10000", "100000", "1000000"})
    public String knowledge;

    @Param({"1", "5", "15"})
    public int k;

    @Param({"ball-goal-index", "ball-goal", "continuous", "tuned", "tuned-scan", "tuned-nearest"})
    public String metric;

    private Recognizer recognizer;
    private ActionSelector selector;
    private List<Scene> queries;
    private final SplittableRandom random = new SplittableRandom(1);
    private int next;

    @Setup
    public void build() {
        boolean recorded = knowledge.equals("krislet");
        boolean remember = BenchSets.remembers(metric);
        KnowledgeBase stored = recorded ? BenchSets.krislet(remember) : BenchSets.synthetic(Integer.parseInt(knowledge), remember);
        queries = recorded ? BenchSets.krisletQueries(remember) : BenchSets.syntheticQueries(remember);
        recognizer = BenchSets.recognizer(stored, metric, k);
        selector = PluginRegistry.load().selector(k == 1 ? "first-valid" : "vote", PluginConfig.DEFAULT);
    }

    @Benchmark
    public Action decide() {
        next = (next + 1) % queries.size();
        return selector.select(recognizer.nearest(queries.get(next)), random);
    }

    private final CpuTimes cpuTimes = new CpuTimes();

    @Setup(Level.Iteration)
    public void startCounting() {
        cpuTimes.reset();
    }

    /**
     * As {@link #decide}, also taking each decision's thread CPU time, whose p50 and p99 are printed
     * after every iteration as a {@code [cpu]} line: on a loaded machine wall-clock samples mostly
     * measure the waits for a core, CPU time does not.
     */
    @Benchmark
    public Action decideCpuTime() {
        return cpuTimes.time(this::decide);
    }

    @TearDown(Level.Iteration)
    public void printCpuTime() {
        String summary = cpuTimes.summary();
        if (summary != null) {
            System.out.printf(Locale.ROOT, "%n[cpu] %s %s k=%d: %s%n", knowledge, metric, k, summary);
        }
    }
}
