package org.scenes.tests.bench;

import java.util.ArrayList;
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
import org.scenes.api.Scene;
import org.scenes.internal.match.KnowledgeBase;

/**
 * The two references of {@link MatchBench} on the sets of {@link ScaleBench} and
 * {@link DecisionBench}, so their scan rates can be set against them: {@code plainReference},
 * the thesis' design (scenes as lists of objects, classes filtered and re-sorted on every
 * comparison, greedy pairing: what {@code continuous} computes), and {@code memoryBandwidth}, a
 * sequential sum over 8 bytes per stored scene. An operation covers {@value #CHUNK} stored scenes,
 * the next chunk each time, so every operation counts the same while successive operations sweep
 * the whole knowledge base, with the cache behaviour of its size. Scores are scenes per second.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = "-Xmx6g")
public class ReferenceBench {
    static final int CHUNK = 10_000;

    /** {@code krislet} (game 1 without Carleton_2) or a synthetic size, at least {@value #CHUNK}. */
    @Param({"krislet", "10000", "100000", "1000000"})
    public String knowledge;

    List<MatchBench.PlainScene> stored;
    List<MatchBench.PlainScene> queries;
    int[] bandwidthData;
    int chunkStart;
    int nextQuery;

    @Setup
    public void build() {
        boolean krislet = knowledge.equals("krislet");
        KnowledgeBase base = krislet ? BenchSets.krislet() : BenchSets.synthetic(Integer.parseInt(knowledge));
        List<Scene> queryScenes = krislet ? BenchSets.krisletQueries() : BenchSets.syntheticQueries();
        stored = new ArrayList<>(base.size());
        for (Scene scene : base.scenes()) {
            stored.add(MatchBench.PlainScene.of(scene));
        }
        queries = queryScenes.stream().map(MatchBench.PlainScene::of).toList();
        bandwidthData = MatchBench.bandwidthData(Math.max(CHUNK, base.size()));
    }

    private int nextChunk() {
        int start = chunkStart;
        chunkStart = start + 2 * CHUNK <= stored.size() ? start + CHUNK : 0;
        return start;
    }

    @Benchmark
    @OperationsPerInvocation(CHUNK)
    public int plainReference() {
        MatchBench.PlainScene query = queries.get(nextQuery);
        nextQuery = (nextQuery + 1) % queries.size();
        int start = nextChunk();
        return query.nearest(stored, start, start + CHUNK);
    }

    @Benchmark
    @OperationsPerInvocation(CHUNK)
    public int memoryBandwidth() {
        int start = 2 * nextChunk();
        return MatchBench.sum(bandwidthData, start, start + 2 * CHUNK);
    }
}
