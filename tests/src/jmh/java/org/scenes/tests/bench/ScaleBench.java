package org.scenes.tests.bench;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.scenes.api.Neighbour;
import org.scenes.api.Scene;
import org.scenes.internal.match.Recognizer;

/**
 * How matching scales: scenes compared per second when one query is scanned over a synthetic
 * knowledge base (k = 1, {@link Recognizer#nearest}) of 10^4 ({@code scan10k}), 10^5
 * ({@code scan100k}) or 10^6 ({@code scan1m}) scenes made by {@link BenchSets#synthetic}; queries
 * are 256 other synthetic scenes, one per operation, in turn. Scores are scenes per second
 * (divide by 10 for scenes per 100 ms cycle). Metrics as in {@link MatchBench}:
 * every built-in one, {@code continuous-optimal}, {@code script-ball-goal}, {@code ball-goal} as
 * its packed scan and {@code ball-goal-index} with its exact index, whose score is the
 * knowledge-base size over the query time, not scenes actually compared.
 *
 * <p>One method per size because {@code OperationsPerInvocation} is a constant; every metric runs
 * at every size (the example script has the encoded form, so it needs no decoded scenes). Each
 * fork generates its knowledge base once (about 20 to 40 s for 10^6 scenes on this machine,
 * printed as a {@code [setup]} line with the heap in use). The compact knowledge
 * base of 10^6 scenes takes about 290 MB and about 530 MB once packed for {@code continuous};
 * packing did not fit in 2 GB before it was chunked, so {@code scan1m} forks get 6 GB.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = "-Xmx2g")
public class ScaleBench {
    /** A synthetic knowledge base of {@link #size()} scenes and a recognizer for one metric; one subclass per size. */
    @State(Scope.Benchmark)
    public abstract static class Knowledge {
        @Param({"ball-goal", "ball-goal-index", "continuous", "continuous-optimal", "cell", "projection", "random", "script-ball-goal"})
        public String metric;

        Recognizer recognizer;
        List<Scene> queries;
        int next;

        abstract int size();

        @Setup
        public void build() {
            recognizer = BenchSets.recognizer(BenchSets.synthetic(size()), metric, 1);
            queries = BenchSets.syntheticQueries();
        }

        List<Neighbour> scan() {
            next = (next + 1) % queries.size();
            return recognizer.nearest(queries.get(next));
        }
    }

    public static class Knowledge10k extends Knowledge {
        @Override
        int size() {
            return 10_000;
        }
    }

    public static class Knowledge100k extends Knowledge {
        @Override
        int size() {
            return 100_000;
        }
    }

    public static class Knowledge1m extends Knowledge {
        @Override
        int size() {
            return 1_000_000;
        }
    }

    @Benchmark
    @OperationsPerInvocation(10_000)
    public List<Neighbour> scan10k(Knowledge10k knowledge) {
        return knowledge.scan();
    }

    @Benchmark
    @OperationsPerInvocation(100_000)
    public List<Neighbour> scan100k(Knowledge100k knowledge) {
        return knowledge.scan();
    }

    /** Room for packing 10^6 scenes for the object-set metrics (see the class comment). */
    @Benchmark
    @OperationsPerInvocation(1_000_000)
    @Fork(value = 1, jvmArgsAppend = "-Xmx6g")
    public List<Neighbour> scan1m(Knowledge1m knowledge) {
        return knowledge.scan();
    }
}
