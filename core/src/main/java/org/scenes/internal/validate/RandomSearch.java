package org.scenes.internal.validate;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.ActionWeights;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginException;
import org.scenes.api.PluginKind;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.TuneDimension;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.scene.SceneFile;

/**
 * The wide search of {@code scenes tune --search random}: seeded random configurations over
 * every object class (ball, goals, flags, lines, players by relation), the three object-set
 * metrics and {@code ball-goal}, both matchings, both spaces, penalties and rows, memory of the
 * previous scene (its directions weighed apart in polar space) and of one to four previous
 * actions (with decay), k and selectors with vote weights; scored by cross-validation on the training files only and narrowed by successive
 * halving: every configuration is scored on a sample of the queries of a subset of the folds,
 * the best third goes on to three times as many, until the last rung scores the survivors on
 * every query of every fold. Configurations that differ only in k and
 * selector share one neighbour search (the k nearest are the first k of the largest k's),
 * knowledge bases are built once per fold and transform, and configurations are scored on all
 * cores. Whatever the threads, results are those of one sequential run.
 */
public final class RandomSearch {
    /** One row of the table of tried configurations: what was scored on how many queries. */
    public record Tried(int id, MatchConfig config, int rung, int queries, double score, double accuracy,
                        double directionAccuracy, double macroF1) {
    }

    /** The winner with its figures over every decision of every fold, and every row tried. */
    public record Result(MatchConfig config, double score, Map<String, Double> figures, List<Tried> table) {
    }

    /**
     * Told after each scored configuration (from any thread): how many so far, of how many
     * planned, and the best score at the highest rung reached yet (its queries are a sample
     * until the last rung).
     */
    public interface Progress {
        void scored(int done, int planned, double bestScore);
    }

    private static final int ETA = 3;
    /** Queries per fold at the first rung, at least, so that small samples still rank. */
    private static final int FIRST_RUNG_QUERIES = 150;
    /** Queries per action type per fold in a sample, at least (all of a type that has fewer). */
    private static final int MIN_PER_ACTION = 8;
    /** 200 configurations: 200, 67, 23, 8, 3; the last rung, on every query, is the dearest. */
    private static final int MAX_RUNGS = 5;

    private final List<SceneFile> files;
    private final PluginRegistry registry;
    private final Folds.Protocol protocol;
    private final Tuner.Objective objective;
    private final List<String> families;
    private final Map<String, List<List<Scene>>> sequences = new ConcurrentHashMap<>();
    private final Map<String, KnowledgeBase> knowledge = new ConcurrentHashMap<>();

    public RandomSearch(List<SceneFile> files, PluginRegistry registry, Folds.Protocol protocol, Tuner.Objective objective) {
        this(files, registry, protocol, objective, List.of());
    }

    /**
     * @param metrics the metrics whose configurations are drawn, each with the same chance; empty:
     *                every family, in the search's own mix
     * @throws PluginException for a name no metric has, or a metric with nothing to search
     */
    public RandomSearch(List<SceneFile> files, PluginRegistry registry, Folds.Protocol protocol, Tuner.Objective objective,
                        List<String> metrics) {
        if (files.size() < 2) {
            throw new IllegalArgumentException("tuning needs at least two training files for cross-validation");
        }
        this.files = List.copyOf(files);
        this.registry = registry;
        this.protocol = protocol;
        this.objective = objective;
        for (String name : metrics) {
            registry.find(PluginKind.METRIC, name);
            if (!OBJECT_FAMILIES.contains(name) && registry.tuneDimensions(PluginKind.METRIC, name).isEmpty()) {
                List<String> searchable = new ArrayList<>(OBJECT_FAMILIES);
                searchable.addAll(otherFamilies());
                throw new PluginException("the metric '" + name + "' declares nothing to search; searchable: "
                        + String.join(", ", searchable));
            }
        }
        this.families = List.copyOf(metrics);
    }

    /**
     * @param configurations how many configurations to try (at least 1)
     * @param deadlineNanos {@link System#nanoTime()} after which no new bracket starts, or
     *                      Long.MAX_VALUE: then one bracket of {@code configurations}
     * @param progress told after each score; may be null
     */
    public Result run(MatchConfig start, long seed, int configurations, long deadlineNanos, Progress progress) {
        SplittableRandom random = new SplittableRandom(seed);
        List<Tried> table = new ArrayList<>();
        AtomicInteger done = new AtomicInteger();
        // the best score at the highest rung reached so far, and that rung
        double[] best = {Double.NEGATIVE_INFINITY, -1};
        MatchConfig winner = null;
        double winnerScore = Double.NEGATIVE_INFINITY;
        LinkedHashSet<MatchConfig> seen = new LinkedHashSet<>();
        boolean timed = deadlineNanos != Long.MAX_VALUE;
        int bracket = timed ? Math.min(configurations, 90) : configurations;
        int planned = planned(bracket);
        do {
            List<MatchConfig> candidates = new ArrayList<>();
            if (seen.isEmpty()) {
                for (MatchConfig known : startingPoints(start)) {
                    boolean drawn = families.isEmpty() || families.contains(known.metric());
                    if (drawn && candidates.size() < bracket && seen.add(known)) {
                        candidates.add(known);
                    }
                }
            }
            for (int attempts = 0; candidates.size() < bracket && attempts < 100 * bracket; attempts++) {
                for (MatchConfig config : randomGroup(start, random)) {
                    if (candidates.size() < bracket && seen.add(config)) {
                        candidates.add(config);
                    }
                }
            }
            if (candidates.isEmpty()) {
                break;
            }
            int total = planned;
            Progress counted = (count, ignored, score) -> {
                if (progress != null) {
                    progress.scored(done.incrementAndGet(), total, best[0]);
                }
            };
            List<Tried> rows = halve(candidates, seed, table.size(), counted, best);
            table.addAll(rows);
            Tried top = rows.get(rows.size() - 1);
            for (Tried row : rows) {
                if (row.rung() == top.rung() && row.score() > top.score() + 1e-12) {
                    top = row;
                }
            }
            if (top.score() > winnerScore + 1e-9) {
                winner = top.config();
                winnerScore = top.score();
            }
            planned += planned(bracket);
        } while (timed && System.nanoTime() < deadlineNanos);
        // the winner's figures over every decision, exactly as validate --folds computes them
        Folds full = Folds.run(files, winner, registry, true, null, protocol);
        ValidationReport pooled = full.pooled();
        Map<String, Double> figures = new LinkedHashMap<>();
        Folds.figures().forEach((name, figure) -> figures.put(name, figure.applyAsDouble(pooled)));
        return new Result(winner, objective.of(pooled), figures, table);
    }

    /**
     * Scores a bracket rung by rung; the rows of every rung, the last rung's last. Each rung
     * spends a third of the next one's queries per configuration: every stride-th query of each
     * fold and action type ({@link #sample}; at least {@link #FIRST_RUNG_QUERIES} per fold), and what that cannot take off comes
     * off the folds (a seeded subset, the same order for every rung, at least two), since each
     * fold costs a pack or index per metric setting; the last rung scores every query of every fold.
     */
    private List<Tried> halve(List<MatchConfig> candidates, long seed, int firstId, Progress progress, double[] best) {
        int longest = files.stream().mapToInt(f -> f.scenes().size()).max().orElse(1);
        int rungs = rungs(candidates.size());
        List<Integer> foldOrder = foldOrder(files.size(), seed);
        List<Tried> rows = new ArrayList<>();
        List<MatchConfig> alive = candidates;
        for (int rung = 0; rung < rungs; rung++) {
            int share = 1;
            for (int r = rung; r < rungs - 1; r++) {
                share *= ETA;
            }
            int stride = Math.max(1, Math.min(share, longest / FIRST_RUNG_QUERIES));
            // what the stride could not take off the budget comes off the folds
            int folds = Math.max(Math.min(2, files.size()), (int) Math.ceil(files.size() * (double) stride / share));
            boolean last = rung == rungs - 1;
            Map<MatchConfig, double[]> scores = score(alive, stride, foldOrder.subList(0, last ? files.size() : folds),
                    rung, progress, best);
            List<MatchConfig> ranked = new ArrayList<>(alive);
            // best first; ties keep the earlier (simpler, or seeded) configuration
            ranked.sort(Comparator.comparingDouble((MatchConfig c) -> -scores.get(c)[0]));
            for (MatchConfig config : alive) {
                double[] s = scores.get(config);
                rows.add(new Tried(firstId + rows.size() + 1, config, rung, (int) s[4], s[0], s[1], s[2], s[3]));
            }
            if (last) {
                break;
            }
            alive = ranked.subList(0, Math.max(1, (ranked.size() + ETA - 1) / ETA));
        }
        return rows;
    }

    /** The folds in a seeded order: each rung scores the first ones. */
    static List<Integer> foldOrder(int folds, long seed) {
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < folds; i++) {
            order.add(i);
        }
        Collections.shuffle(order, new Random(seed));
        return order;
    }

    /** Rungs of a bracket: until a ETA-th of the candidates is at most ETA, at most {@link #MAX_RUNGS}. */
    private static int rungs(int candidates) {
        int rungs = 1;
        for (int n = candidates; n > ETA && rungs < MAX_RUNGS; n = (n + ETA - 1) / ETA) {
            rungs++;
        }
        return rungs;
    }

    private static int planned(int bracket) {
        int planned = 0;
        int rungs = rungs(bracket);
        for (int n = bracket, r = 0; r < rungs; r++, n = Math.max(1, (n + ETA - 1) / ETA)) {
            planned += n;
        }
        return planned;
    }

    /**
     * Scores on every stride-th query of each fold: per configuration {score, accuracy,
     * direction, macro F1, queries}. Configurations sharing metric and transforms share one
     * neighbour search per fold, at their largest k.
     */
    private Map<MatchConfig, double[]> score(List<MatchConfig> configs, int stride, List<Integer> folds, int rung,
                                             Progress progress, double[] best) {
        Map<String, List<MatchConfig>> groups = new LinkedHashMap<>();
        for (MatchConfig config : configs) {
            groups.computeIfAbsent(searchKey(config), key -> new ArrayList<>()).add(config);
        }
        Map<MatchConfig, double[]> scores = new ConcurrentHashMap<>();
        groups.values().parallelStream().forEach(group -> {
            Map<MatchConfig, List<ValidationReport>> reports = new HashMap<>();
            int kMax = group.stream().mapToInt(MatchConfig::k).max().orElse(1);
            MatchConfig first = group.get(0);
            List<List<Scene>> sequences = sequences(first);
            int queries = 0;
            for (int fold : folds) {
                KnowledgeBase train = knowledge(first, fold);
                Recognizer recognizer = first.recognizer(train, registry, kMax);
                List<Scene> all = sequences.get(fold);
                List<Scene> test = new ArrayList<>();
                List<List<Neighbour>> found = new ArrayList<>();
                List<Integer> positions = new ArrayList<>();
                int[] sample = sample(all, stride);
                long[] nanos = new long[sample.length];
                for (int q = 0; q < sample.length; q++) {
                    int i = sample[q];
                    long begin = System.nanoTime();
                    found.add(recognizer.nearest(all.get(i)));
                    nanos[q] = System.nanoTime() - begin;
                    test.add(all.get(i));
                    positions.add(i);
                }
                queries += test.size();
                for (MatchConfig config : group) {
                    ActionSelector selector = config.selectorFactory(registry).get();
                    Action[] truth = new Action[test.size()];
                    Action[] predicted = new Action[test.size()];
                    for (int q = 0; q < test.size(); q++) {
                        List<Neighbour> nearest = found.get(q);
                        List<Neighbour> mine = nearest.subList(0, Math.min(config.k(), nearest.size()));
                        truth[q] = test.get(q).primaryAction();
                        predicted[q] = selector.select(mine, Validator.queryRandom(config.seed(), positions.get(q)));
                    }
                    // the primary action's figures only: what the objectives read (the winner gets the full report)
                    reports.computeIfAbsent(config, c -> new ArrayList<>())
                            .add(ValidationReport.of(train.size(), truth, predicted, nanos));
                }
            }
            for (MatchConfig config : group) {
                ValidationReport pooled = ValidationReport.pooled(reports.get(config));
                double value = objective.of(pooled);
                scores.put(config, new double[] {value, pooled.accuracy(), pooled.directionAccuracy(), pooled.macroF1(), queries});
                synchronized (best) {
                    if (rung > best[1]) {
                        best[0] = value;
                        best[1] = rung;
                    } else if (rung == best[1]) {
                        best[0] = Math.max(best[0], value);
                    }
                }
                progress.scored(0, 0, value);
            }
        });
        return scores;
    }

    /**
     * The positions a rung queries in one fold, ascending: every stride-th scene of each action
     * type (so each type keeps its share), and at least {@link #MIN_PER_ACTION} of a rarer one (all
     * of it when it has fewer), since a sample holding no kick scores kick F1, and so macro F1, as noise.
     * Stride 1 is every scene.
     */
    static int[] sample(List<Scene> scenes, int stride) {
        Map<ActionType, List<Integer>> byType = new EnumMap<>(ActionType.class);
        for (int i = 0; i < scenes.size(); i++) {
            byType.computeIfAbsent(scenes.get(i).actionType(), type -> new ArrayList<>()).add(i);
        }
        List<Integer> chosen = new ArrayList<>();
        for (List<Integer> members : byType.values()) {
            int take = Math.min(members.size(), Math.max(MIN_PER_ACTION, (members.size() + stride - 1) / stride));
            for (int j = 0; j < take; j++) {
                chosen.add(members.get((int) ((long) j * members.size() / take))); // evenly spread over the fold
            }
        }
        return chosen.stream().mapToInt(Integer::intValue).sorted().toArray();
    }

    /** What decides the neighbours: all but k, selector, action weights and seed. */
    private static String searchKey(MatchConfig config) {
        return config.metric() + "|" + new TreeMap<>(config.metricOptions()) + "|" + config.objectWeights().format()
                + "|" + config.transforms();
    }

    private List<List<Scene>> sequences(MatchConfig config) {
        return sequences.computeIfAbsent(config.transforms().toString(), key -> {
            List<List<Scene>> transformed = new ArrayList<>();
            for (SceneFile file : files) {
                transformed.add(KnowledgeBase.transform(file.scenes(), config.transformFactory(registry).get()));
            }
            return transformed;
        });
    }

    /** The training knowledge base of a fold, as {@link Folds} builds it, once per transform. */
    private KnowledgeBase knowledge(MatchConfig config, int fold) {
        List<List<Scene>> transformed = sequences(config);
        return knowledge.computeIfAbsent(config.transforms() + "#" + fold, key -> {
            List<Scene> scenes = new ArrayList<>();
            if (protocol == Folds.Protocol.NEXT) {
                scenes.addAll(transformed.get((fold + 1) % files.size()));
            } else {
                for (int j = 0; j < files.size(); j++) {
                    if (j != fold) {
                        scenes.addAll(transformed.get(j));
                    }
                }
            }
            return KnowledgeBase.held(files.get(0).grid(), scenes); // the sequences are kept: no decoding per pack
        });
    }

    /** Configurations every search starts with: the thesis' ball-goal and the best of the coordinate descent's families. */
    static List<MatchConfig> startingPoints(MatchConfig start) {
        List<MatchConfig> known = new ArrayList<>();
        known.add(start.withMetric("ball-goal", Map.of()).withObjectWeights(ObjectWeights.parse("ball=1,goal=1"))
                .withK(1).withSelector("first-valid", Map.of()));
        Map<String, String> tuned = new HashMap<>(Map.of("space", "polar", "log-distance", "true", "distance-weight", "30",
                "direction-weight", "10", "row-weight", "1000", "penalty", "20000", "penalty-scale", "10000"));
        MatchConfig polar = start.withMetric("continuous", tuned).withObjectWeights(ObjectWeights.parse("ball=1,goal=0.05"))
                .withK(1).withSelector("first-valid", Map.of());
        known.add(Tuner.withMemory(polar, 0, 100));
        known.add(polar);
        return known;
    }

    private static final double[] GOALS = {0, 0.02, 0.05, 0.1, 0.3, 1};

    /** One random metric setting with three of its k and selector variants. */
    private List<MatchConfig> randomGroup(MatchConfig start, SplittableRandom random) {
        MatchConfig metric = randomMetric(start, random);
        List<MatchConfig> variants = new ArrayList<>(List.of(
                metric.withK(1).withSelector("first-valid", Map.of()),
                metric.withK(3).withSelector("vote", Map.of()),
                metric.withK(5).withSelector("vote", Map.of()),
                metric.withK(7).withSelector("vote", Map.of()),
                metric.withK(5).withSelector("vote", Map.of("params", "average")),
                metric.withK(3).withSelector("vote", Map.of()).withActionWeights(ActionWeights.parse("kick=3")),
                metric.withK(5).withSelector("vote", Map.of()).withActionWeights(ActionWeights.parse("kick=2,turn=1.5"))));
        List<MatchConfig> chosen = new ArrayList<>();
        chosen.add(variants.remove(0)); // k = 1 always: the fastest decision, and often the best
        for (int i = 0; i < 2; i++) {
            chosen.add(variants.remove(random.nextInt(variants.size())));
        }
        return chosen;
    }

    /** The object families this search mixes itself; any other metric declaring dimensions is searched as declared. */
    private static final List<String> OBJECT_FAMILIES = List.of("ball-goal", "continuous", "projection", "cell");

    /** Metrics with tune dimensions of their own, outside the object families, by name. */
    private List<String> otherFamilies() {
        return registry.names(PluginKind.METRIC).stream()
                .filter(name -> !OBJECT_FAMILIES.contains(name))
                .filter(name -> !registry.tuneDimensions(PluginKind.METRIC, name).isEmpty())
                .sorted().toList();
    }

    /** The metric of the next setting: one of those asked for, or the search's own mix of every family. */
    private String drawFamily(SplittableRandom random) {
        if (!families.isEmpty()) {
            return families.get(random.nextInt(families.size()));
        }
        List<String> others = otherFamilies();
        int family = random.nextInt(20 + 3 * others.size());
        if (family >= 20) {
            return others.get((family - 20) / 3);
        }
        return family < 3 ? "ball-goal" : family < 14 ? "continuous" : family < 17 ? "projection" : "cell";
    }

    /**
     * One random metric setting. What to search in a metric's own options, and over which values,
     * the metric's provider declares ({@link org.scenes.api.TuneDimension}); what spans plugins
     * (memory, which needs the memory transform and a metric reading it, object weights, the family
     * mix) is this search's.
     */
    private MatchConfig randomMetric(MatchConfig start, SplittableRandom random) {
        double memory = pick(random, 0, 0, 0, 0.03, 0.1, 0.3, 1);
        double memoryAction = pick(random, 0, 0, 10, 100, 100, 1000);
        // deeper memory of actions: 2 to 4 actions back, each further one weighing decay times the last
        int depth = memoryAction > 0 && random.nextInt(3) == 0 ? 2 + random.nextInt(3) : 1;
        double decay = pick(random, 0.3, 0.5, 1);
        String name = drawFamily(random);
        if (!OBJECT_FAMILIES.contains(name)) {
            // a family of its own (world-model metrics such as field): each dimension it declares, drawn
            Map<String, String> options = new HashMap<>();
            for (TuneDimension dimension : registry.tuneDimensions(PluginKind.METRIC, name).values()) {
                options.put(dimension.option(), format(pick(random, dimension.valueArray())));
            }
            return start.withMetric(name, options);
        }
        if (name.equals("ball-goal")) {
            Map<String, TuneDimension> ballGoal = registry.tuneDimensions(PluginKind.METRIC, "ball-goal");
            Map<String, String> options = new HashMap<>();
            for (TuneDimension dimension : ballGoal.values()) {
                options.put(dimension.option(), format(pick(random, dimension.valueArray())));
            }
            MatchConfig config = start.withMetric("ball-goal", options)
                    .withObjectWeights(ObjectWeights.of(1, pick(random, 0.3, 1, 3), 0, 0, 0, 0, 0, 0));
            return Tuner.withMemory(config, memory, memoryAction);
        }
        Map<String, TuneDimension> declared = registry.tuneDimensions(PluginKind.METRIC, name);
        Map<String, String> accepted = registry.find(PluginKind.METRIC, name).options();
        double goal = pick(random, GOALS);
        double flag = random.nextInt(4) == 0 ? pick(random, 0.001, 0.005, 0.02, 0.05) : 0;
        double line = random.nextInt(5) == 0 ? pick(random, 0.005, 0.02, 0.1) : 0;
        double allPlayers = 0;
        double teammates = 0;
        double opponents = 0;
        double unknownPlayers = 0;
        int players = random.nextInt(10);
        if (players == 0) {
            allPlayers = pick(random, 0.005, 0.02, 0.1);
        } else if (players <= 2) {
            teammates = pick(random, 0, 0.005, 0.02, 0.1);
            opponents = pick(random, 0, 0.005, 0.02, 0.1);
            unknownPlayers = pick(random, 0, 0.005, 0.02);
        }
        ObjectWeights weights = new ObjectWeights(1, goal, flag, line, allPlayers, teammates, opponents, unknownPlayers);
        boolean lowDimensional = flag == 0 && line == 0 && allPlayers == 0 && teammates == 0 && opponents == 0
                && unknownPlayers == 0;
        if (!lowDimensional) {
            // the previous scene's flags, lines or players: no packed form, each query decodes and
            // compares whole scenes (the dearest configurations by far); memory of actions packs
            memory = 0;
        }
        Map<String, String> options = new HashMap<>();
        // optimal matching only where groups are small: over flags it is far slower and rarely better
        if (lowDimensional && random.nextInt(3) == 0) {
            options.put("matching", "optimal");
        }
        boolean polar = declared.containsKey("direction-weight") && random.nextInt(10) < 7;
        if (polar) {
            options.put("space", "polar");
            draw(options, random, declared, "distance-weight");
            double direction = draw(options, random, declared, "direction-weight");
            if (memory > 0 && random.nextBoolean()) {
                // the previous scene's directions weighed less than the current one's (better for Krislet)
                options.put("memory-direction-weight", format(direction * pick(random, 0.1, 0.3)));
            }
        }
        if (accepted.containsKey("log-distance") && random.nextInt(10) < 7) {
            options.put("log-distance", "true");
        }
        if (random.nextBoolean()) {
            // dead ahead apart from either side (Krislet dashes only at 0 degrees)
            draw(options, random, declared, "side-weight");
        }
        double rows = draw(options, random, declared, "row-weight");
        if (rows > 0 && memory > 0 && random.nextBoolean()) {
            // the remembered scene's rings weighed less than the current one's
            options.put("memory-row-weight", format(rows * pick(random, 0.1, 0.3)));
        }
        if (random.nextInt(3) == 0) {
            options.put("own-goal-weight", "0"); // only the goal attacked
        }
        draw(options, random, declared, "penalty");
        draw(options, random, declared, "penalty-scale");
        if (declared.containsKey("cycles")) { // a projecting metric
            draw(options, random, declared, "cycles");
        }
        MatchConfig config = Tuner.withMemory(start.withMetric(name, options).withObjectWeights(weights),
                memory, memoryAction);
        return depth == 1 ? config : withMemoryDepth(config, depth, decay);
    }

    /** Memory of {@code depth} actions back, which needs the transform that carries them. */
    static MatchConfig withMemoryDepth(MatchConfig config, int depth, double decay) {
        Map<String, String> options = new HashMap<>(config.metricOptions());
        options.put("memory-depth", Integer.toString(depth));
        options.put("memory-decay", format(decay));
        return config.withMetric(config.metric(), options).withTransforms(List.of("long-memory"));
    }

    /**
     * One of the values a metric declares for an option, set in {@code options} (a log dimension's 0
     * leaves the option out); a metric that declares none cannot be searched.
     */
    private static double draw(Map<String, String> options, SplittableRandom random, Map<String, TuneDimension> declared,
                               String option) {
        TuneDimension dimension = declared.get(option);
        if (dimension == null) {
            throw new IllegalStateException("the metric declares no tune dimension '" + option + "' (its dimensions: "
                    + declared.keySet() + ")");
        }
        double value = pick(random, dimension.valueArray());
        if (value != 0 || dimension.scale() == TuneDimension.Scale.LINEAR) {
            options.put(option, format(value));
        }
        return value;
    }

    private static double pick(SplittableRandom random, double... values) {
        return values[random.nextInt(values.length)];
    }

    private static String format(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
    }
}
