package org.scenes.tests.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
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
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * Scenes compared per second when one query is scanned over the whole knowledge base (k = 1),
 * as each decision of the agent does. The knowledge base is the first {@value #SCENES} scenes of
 * the Krislet classic game 1 players other than Carleton_2, converted in the setup; queries are
 * {@value #QUERIES} of Carleton_2's scenes spread over its game, one per operation, taken with a
 * stride of {@value #QUERY_STRIDE} so that the operations of any iteration sample the whole
 * game rather than one stretch of similar scenes. Scores are scenes per second: divide by 10
 * for scenes per 100 ms cycle.
 * <ul>
 *   <li>{@code scan}: the {@link Recognizer} with the metric named by {@code metric}
 *       ({@code continuous-optimal} is {@code continuous} with {@code matching=optimal};
 *       {@code ball-goal} is its packed scan, {@code index=false}, and {@code ball-goal-index} its
 *       exact index, whose score is an equivalent rate: stored scenes divided by decision time;
 *       {@code script-ball-goal} is the shipped example script);</li>
 *   <li>{@code scanAllQueries}: the same, one operation being every query once, so the score
 *       is the rate over the whole query set whatever the iteration length (scans whose cost
 *       depends much on the query, such as optimal matching's pruning, cannot pick lucky ones);</li>
 *   <li>{@code plainReference}: the thesis' design on the same data: scenes as lists of objects,
 *       each comparison filtering and re-sorting every class's objects, greedy pairing of all
 *       objects in cartesian space (what {@code continuous} computes), so the ratio to
 *       {@code scan} with {@code continuous} is measured in the same run;</li>
 *   <li>{@code memoryBandwidth}: a sequential sum over an int array of 8 bytes per scene (the
 *       packed ball-goal data takes 6), the hardware reference for a one-pass scan.</li>
 * </ul>
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = "-Xmx1g")
public class MatchBench {
    static final int SCENES = 16384;
    static final int QUERIES = 256;
    static final int QUERY_STRIDE = 97;
    private static final String[] STORED = {"Carleton_1", "Carleton_3", "Carleton_4", "Carleton_5",
        "University_1", "University_2", "University_3", "University_4", "University_5"};

    /** The knowledge base and queries, converted once per fork. */
    @State(Scope.Benchmark)
    public static class Data {
        List<Scene> stored;
        List<Scene> queries;
        List<PlainScene> plainStored;
        List<PlainScene> plainQueries;
        int[] bandwidthData;
        int next;

        @Setup
        public void load() throws IOException {
            Path game = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet", "classic-game1");
            stored = new ArrayList<>();
            for (String player : STORED) {
                for (Scene scene : scenes(game.resolve(player + ".lsf.gz"))) {
                    if (stored.size() < SCENES) {
                        stored.add(scene);
                    }
                }
            }
            if (stored.size() < SCENES) {
                throw new IllegalStateException("game 1 holds only " + stored.size() + " scenes, fewer than " + SCENES);
            }
            List<Scene> test = scenes(game.resolve("Carleton_2.lsf.gz"));
            queries = new ArrayList<>();
            for (int i = 0; i < QUERIES; i++) {
                queries.add(test.get(i * test.size() / QUERIES));
            }
            plainStored = stored.stream().map(PlainScene::of).toList();
            plainQueries = queries.stream().map(PlainScene::of).toList();
            bandwidthData = bandwidthData(SCENES);
        }

        int nextQuery() {
            next = (next + QUERY_STRIDE) % QUERIES; // odd stride: every query once per QUERIES operations
            return next;
        }
    }

    /** A recognizer over the data with the metric named by {@code metric}. */
    @State(Scope.Benchmark)
    public static class Matcher {
        @Param({"ball-goal", "ball-goal-index", "continuous", "continuous-optimal", "cell", "projection", "random", "script-ball-goal"})
        public String metric;

        Recognizer recognizer;

        @Setup
        public void build(Data data) {
            recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, data.stored), BenchSets.metric(metric), 1);
        }
    }

    private static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build().convert(log, scenes::add);
        return scenes;
    }

    @Benchmark
    @OperationsPerInvocation(SCENES)
    public List<Neighbour> scan(Data data, Matcher matcher) {
        return matcher.recognizer.nearest(data.queries.get(data.nextQuery()));
    }

    @Benchmark
    @OperationsPerInvocation(SCENES * QUERIES)
    public int scanAllQueries(Data data, Matcher matcher) {
        int sum = 0;
        for (Scene query : data.queries) {
            sum += matcher.recognizer.nearest(query).get(0).index();
        }
        return sum;
    }

    @Benchmark
    @OperationsPerInvocation(SCENES)
    public int plainReference(Data data) {
        return data.plainQueries.get(data.nextQuery()).nearest(data.plainStored, 0, data.plainStored.size());
    }

    @Benchmark
    @OperationsPerInvocation(SCENES)
    public int memoryBandwidth(Data data) {
        return sum(data.bandwidthData, 0, data.bandwidthData.length);
    }

    /** Data for the memory-bandwidth reference: 8 bytes per stored scene. */
    static int[] bandwidthData(int scenes) {
        int[] data = new int[scenes * 2];
        for (int i = 0; i < data.length; i++) {
            data[i] = i * 31;
        }
        return data;
    }

    /** The memory-bandwidth reference: a sequential sum over {@code values[from, to)}. */
    static int sum(int[] values, int from, int to) {
        int sum = 0;
        for (int i = from; i < to; i++) {
            sum += values[i];
        }
        return sum;
    }

    /** The thesis' object model: an object is its class and position, a scene a list of them. */
    record PlainObject(int group, double x, double y, double distance) {
    }

    record PlainScene(List<PlainObject> objects) {
        static final int GROUPS = 9;

        static PlainScene of(Scene scene) {
            List<PlainObject> objects = new ArrayList<>();
            for (SeenObject object : scene.objects()) {
                double r = Double.isNaN(object.distance()) ? 100 : object.distance();
                double radians = Math.toRadians(Double.isNaN(object.direction()) ? 0 : object.direction());
                objects.add(new PlainObject(group(object), r * Math.cos(radians), r * Math.sin(radians), r));
            }
            return new PlainScene(objects);
        }

        private static int group(SeenObject object) {
            return switch (object.kind()) {
                case BALL -> 0;
                case GOAL -> object.relation() == Relation.OWN ? 1 : object.relation() == Relation.OPPONENT ? 2 : 3;
                case FLAG -> 4;
                case LINE -> 5;
                case PLAYER -> object.relation() == Relation.TEAMMATE ? 6 : object.relation() == Relation.OPPONENT ? 7 : 8;
            };
        }

        /** Index of the scene of {@code stored[from, to)} nearest to this one, the first of equals. */
        int nearest(List<PlainScene> stored, int from, int to) {
            double best = Double.POSITIVE_INFINITY;
            int bestIndex = -1;
            for (int i = from; i < to; i++) {
                double distance = distance(stored.get(i));
                if (distance < best) {
                    best = distance;
                    bestIndex = i;
                }
            }
            return bestIndex;
        }

        /** Per class: both sides' objects collected and sorted again, paired in order, leftovers penalised. */
        double distance(PlainScene other) {
            double total = 0;
            for (int group = 0; group < GROUPS; group++) {
                List<PlainObject> mine = inGroup(group);
                List<PlainObject> theirs = other.inGroup(group);
                int paired = Math.min(mine.size(), theirs.size());
                for (int i = 0; i < paired; i++) {
                    total += Math.hypot(mine.get(i).x() - theirs.get(i).x(), mine.get(i).y() - theirs.get(i).y());
                }
                for (int i = paired; i < mine.size(); i++) {
                    total += penalty(mine.get(i));
                }
                for (int i = paired; i < theirs.size(); i++) {
                    total += penalty(theirs.get(i));
                }
            }
            return total;
        }

        private List<PlainObject> inGroup(int group) {
            List<PlainObject> selected = new ArrayList<>();
            for (PlainObject object : objects) {
                if (object.group() == group) {
                    selected.add(object);
                }
            }
            selected.sort(Comparator.comparingDouble(PlainObject::distance));
            return selected;
        }

        private static double penalty(PlainObject object) {
            return 10 * 10 / (10 + object.distance());
        }
    }
}
