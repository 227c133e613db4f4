package org.scenes.tests.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
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
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.target.Destinations;
import org.scenes.internal.target.Replay;
import org.scenes.internal.target.Steering;
import org.scenes.internal.validate.Validator;
import org.scenes.simulator.SyntheticScenes;

/**
 * Latency of one decision of the HELIOS imitators' configuration (examples/configs/helios.json:
 * {@code field}, k = 1 since 2026-12-07, k = 10 before; its {@code opponent-weight=3} since the same
 * day, given as {@code -p options=opponent-weight=3}) over 10^6 stored scenes, sampled per call so
 * JMH reports percentiles (p0.99); the decision is {@link Recognizer#nearest}, neighbours decoded,
 * then first-valid's choice ({@link #decideAsAgent}: and what the live agent adds, a look further
 * when the choice sends no body command and target replay).
 *
 * <p>{@code knowledge=helios}: each stored scene is a random real scene of HELIOS base games 1, 3
 * and 4 (directories {@code sc1}, {@code sc3}, {@code sc4} under the {@code scenes.helios}
 * property, both teams) whose world model is jittered (own position and the ball by up to 0.5 m,
 * ball velocity by up to 0.05 m/cycle, body by up to 5 degrees, stamina by up to 100), so play
 * modes, ball states, who chases and the joint spread of the features follow real play; the
 * other parts of the scene (seen objects, remembered players, actions) are the source's, shared.
 * Queries are game 5's {@code HELIOS_A_*} scenes (not stored), spread evenly. {@code
 * knowledge=synthetic} is {@code scenes bench --synthetic}'s set: Krislet moments whose world
 * model is the observer's true state, one play mode and no remembered players, with synthetic
 * queries; uniform over the pitch, so harder for a tree than real play and blind to the fixed costs.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = "-Xmx4g")
public class FieldIndexBench {
    private static final int QUERIES = 1024;
    private static final String[] STORED_GAMES = {"sc1", "sc3", "sc4"};
    private static final String QUERY_GAME = "sc5";

    @Param({"1000000"})
    public int scenes;

    @Param({"10"})
    public int k;

    @Param({"helios", "synthetic"})
    public String knowledge;

    @Param({"index"})
    public String search;

    /**
     * {@code spread}: 1,024 queries spread evenly over game 5, each far from the one before.
     * {@code played}: every scene of game 5's {@code HELIOS_A_*} files in order, one player's game
     * after another, as a live player asks them cycle after cycle (consecutive queries share
     * neighbours); HELIOS knowledge only.
     */
    @Param({"spread"})
    public String queries;

    /** {@code field}'s options, as KEY=VALUE pairs separated by semicolons (JMH splits values at commas); empty: its defaults. */
    @Param({""})
    public String options;

    private Recognizer recognizer;
    private ActionSelector selector;
    private Destinations destinations;
    /** one player's memory of its previous turns, as the live agent keeps it from decision to decision */
    private final Steering steering = new Steering();
    private List<Scene> asked;
    private final SplittableRandom random = new SplittableRandom(1);
    private int next;
    private final CpuTimes cpuTimes = new CpuTimes();

    @Setup
    public void build() {
        long start = System.nanoTime();
        KnowledgeBase stored;
        if (knowledge.equals("helios")) {
            Path root = Path.of(System.getProperty("scenes.helios", "/work/tmp/hel"));
            List<Scene> test = read(root.resolve(QUERY_GAME), "HELIOS_A_");
            asked = queries.equals("played") ? test : spread(test);
            stored = jitteredKnowledge(root);
        } else {
            KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
            SyntheticScenes.generate(BenchSets.KNOWLEDGE_SEED, scenes, Grid.DEFAULT, builder::add);
            stored = builder.build();
            asked = new ArrayList<>(QUERIES);
            SyntheticScenes.generate(BenchSets.QUERY_SEED, QUERIES, Grid.DEFAULT, asked::add);
        }
        PluginRegistry registry = PluginRegistry.load();
        Map<String, String> fieldOptions = BenchSets.options(options.split(";"));
        if (search.equals("scan")) {
            fieldOptions.put("index", "false");
        }
        PluginConfig config = PluginConfig.DEFAULT.withOptions(fieldOptions);
        recognizer = new Recognizer(stored, () -> registry.metric("field", config), k);
        selector = registry.selector("first-valid", PluginConfig.DEFAULT);
        destinations = Destinations.of(stored);
        System.out.printf("%n%,d %s scenes stored, index built, in %.1f s%n", stored.size(), knowledge,
                (System.nanoTime() - start) / 1e9);
    }

    /** {@link #QUERIES} of the scenes, evenly spaced. */
    private static List<Scene> spread(List<Scene> scenes) {
        List<Scene> spread = new ArrayList<>(QUERIES);
        for (int i = 0; i < QUERIES; i++) {
            spread.add(scenes.get((int) ((long) i * scenes.size() / QUERIES)));
        }
        return spread;
    }

    /** The stored scenes; the real ones they are drawn from are garbage once this returns. */
    private KnowledgeBase jitteredKnowledge(Path root) {
        List<Scene> real = new ArrayList<>();
        for (String game : STORED_GAMES) {
            real.addAll(read(root.resolve(game), "HELIOS_"));
        }
        Random random = new Random(42);
        KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
        for (int i = 0; i < scenes; i++) {
            builder.add(jittered(real.get(random.nextInt(real.size())), random));
        }
        return builder.build();
    }

    /** Every scene of the files in {@code directory} whose names start with {@code prefix}, in name order. */
    private static List<Scene> read(Path directory, String prefix) {
        List<Path> files = new ArrayList<>();
        try (DirectoryStream<Path> listing = Files.newDirectoryStream(directory, prefix + "*.json.gz")) {
            listing.forEach(files::add);
        } catch (IOException e) {
            throw new UncheckedIOException("FieldIndexBench needs the HELIOS scene files (-Dscenes.helios=DIR with sc1,"
                    + " sc3, sc4, sc5): " + e.getMessage(), e);
        }
        files.sort(null);
        List<Scene> scenes = new ArrayList<>();
        files.forEach(file -> scenes.addAll(SceneFileReader.read(file).scenes()));
        if (scenes.isEmpty()) {
            throw new IllegalStateException("no " + prefix + "*.json.gz scenes in " + directory);
        }
        return scenes;
    }

    /** The scene with its world model's own position, ball, body and stamina moved a little. */
    static Scene jittered(Scene source, Random random) {
        World w = source.world();
        if (w == null || !w.located()) {
            return source;
        }
        World moved = new World(w.x() + jitter(random, 0.5), w.y() + jitter(random, 0.5), w.body() + jitter(random, 5),
                w.neck(), w.vx(), w.vy(), w.stamina() + jitter(random, 100), w.effort(), w.age(),
                w.ballX() + jitter(random, 0.5), w.ballY() + jitter(random, 0.5), w.ballVx() + jitter(random, 0.05),
                w.ballVy() + jitter(random, 0.05), w.ballAge(), w.players(), w.playMode(), w.ownScore(),
                w.opponentScore());
        return source.withWorld(moved);
    }

    private static double jitter(Random random, double range) {
        return (random.nextDouble() * 2 - 1) * range;
    }

    /** The neighbour search alone. */
    @Benchmark
    public List<Neighbour> nearest() {
        next = (next + 1) % asked.size();
        return recognizer.nearest(asked.get(next));
    }

    /** A decision as the configuration takes it: the search, then first-valid's choice. */
    @Benchmark
    public Action decide() {
        next = (next + 1) % asked.size();
        return selector.select(recognizer.nearest(asked.get(next)), random);
    }

    /**
     * A decision as the live agent takes it with examples/configs/helios.json (ImitationBrain's
     * decide): the search, first-valid's choice, then the target replay of {@link
     * Validator#prediction}, which reads every neighbour's actions and one donor's world; its CPU
     * time is taken as {@link #decideCpuTime}'s. The jittered knowledge base stores scenes in
     * random order, so few have a known destination; the replay's other work is the agent's.
     */
    @Benchmark
    public List<Action> decideAsAgent() {
        return cpuTimes.time(() -> {
            next = (next + 1) % asked.size();
            Scene query = asked.get(next);
            List<Neighbour> nearest = recognizer.nearest(query);
            ImitationBrain.Choice choice = ImitationBrain.lookFurther(new ImitationBrain.Choice(nearest,
                    nearest.isEmpty() ? null : selector.select(nearest, random)), recognizer, query, selector, random);
            return Validator.prediction(choice.action(), choice.nearest(), query, Replay.TARGET, destinations,
                    steering);
        });
    }

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
            System.out.printf(Locale.ROOT, "%n[cpu] field %s %d k=%d: %s%n", knowledge, scenes, k, summary);
        }
    }
}
