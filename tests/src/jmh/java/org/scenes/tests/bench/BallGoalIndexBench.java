package org.scenes.tests.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
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
import org.scenes.api.ObjectKind;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * Latency of one decision's k-NN search ({@link Recognizer#nearest}) with {@code ball-goal} over
 * knowledge bases of 10^4 to 10^6 scenes, sampled per call so JMH reports percentiles (p0.99).
 * {@code search=index} is the default recognizer (the exact index); {@code search=scan} sets the
 * metric option {@code index=false}, the packed scan of every scene, for the ratio.
 *
 * <p>The knowledge base is synthetic but shaped like real play: each scene copies a random real
 * scene of Krislet classic game 1 (players other than Carleton_2), keeps its objects (about 20
 * flags, lines and players, shared instances rather than copies, so 10^6 scenes fit the heap)
 * and replaces its ball and opponent goal by ones at the same distance with the direction
 * jittered by up to 3 degrees (integer, as the server sends), cells recomputed; so cells,
 * directions, absences and their joint distribution follow real scenes. Queries are Carleton_2's
 * real scenes, one per call, in turn.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = "-Xmx2g")
public class BallGoalIndexBench {
    private static final int QUERIES = 256;
    private static final int JITTER = 3;
    private static final String[] SOURCES = {"Carleton_1", "Carleton_3", "Carleton_4", "Carleton_5",
        "University_1", "University_2", "University_3", "University_4", "University_5"};

    @Param({"10000", "100000", "1000000"})
    public int scenes;

    @Param({"1", "5", "15"})
    public int k;

    @Param({"index"})
    public String search;

    private Recognizer recognizer;
    private List<Scene> queries;
    private int next;

    @Setup
    public void build() throws IOException {
        Path game = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet", "classic-game1");
        List<Scene> real = new ArrayList<>();
        for (String player : SOURCES) {
            real.addAll(convert(game.resolve(player + ".lsf.gz")));
        }
        Random random = new Random(42);
        List<Scene> stored = new ArrayList<>(scenes);
        for (int i = 0; i < scenes; i++) {
            stored.add(resample(real.get(random.nextInt(real.size())), random));
        }
        List<Scene> test = convert(game.resolve("Carleton_2.lsf.gz"));
        queries = new ArrayList<>();
        for (int i = 0; i < QUERIES; i++) {
            queries.add(test.get(i * test.size() / QUERIES));
        }
        PluginRegistry registry = PluginRegistry.load();
        PluginConfig config = PluginConfig.DEFAULT.withOptions(
                search.equals("scan") ? Map.of("index", "false") : Map.of());
        recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), () -> registry.metric("ball-goal", config), k);
    }

    /** The scene with its ball and opponent goal moved by a small integer turn; every other object kept. */
    private static Scene resample(Scene source, Random random) {
        List<SeenObject> objects = new ArrayList<>(source.objects().size());
        for (SeenObject object : source.objects()) {
            boolean ballOrGoal = object.kind() == ObjectKind.BALL
                    || object.kind() == ObjectKind.GOAL && object.relation() == Relation.OPPONENT;
            if (ballOrGoal && !Double.isNaN(object.direction())) {
                double direction = object.direction() + random.nextInt(2 * JITTER + 1) - JITTER;
                objects.add(SeenObject.simple(object.kind(), object.name(), object.relation(), object.distance(),
                        direction, Grid.DEFAULT));
            } else {
                objects.add(object);
            }
        }
        return new Scene(source.cycle(), source.observer(), objects, source.actions());
    }

    private static List<Scene> convert(Path log) throws IOException {
        List<Scene> converted = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build().convert(log, converted::add);
        return converted;
    }

    @Benchmark
    public List<Neighbour> nearest() {
        next = (next + 1) % QUERIES;
        return recognizer.nearest(queries.get(next));
    }
}
