package org.scenes.internal.validate;

import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Supplier;
import java.util.stream.IntStream;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.target.Destinations;
import org.scenes.internal.target.Replay;
import org.scenes.internal.target.Steering;
import org.scenes.internal.target.Targets;
import org.scenes.internal.world.ServerDefaults;

/**
 * Asks the recognizer and selector for an action on every test scene and compares it with
 * the action recorded there. Queries run in parallel over the cores; each query draws its
 * random numbers from its own generator seeded by the run's seed and the query's index, so
 * a parallel run gives exactly the results of a sequential one.
 */
public final class Validator {
    private Validator() {
    }

    /**
     * @param progress called once per finished query (from any thread); may be null
     */
    public static ValidationReport run(Recognizer recognizer, Supplier<ActionSelector> selectors, List<Scene> test,
                                       long seed, boolean parallel, Runnable progress) {
        return run(recognizer, selectors, test, seed, Replay.RAW, parallel, progress);
    }

    /**
     * @param replay how the chosen scene's actions become the prediction: as recorded, or as their
     *               targets reached from the test scene's world model
     * @param progress called once per finished query (from any thread); may be null
     */
    public static ValidationReport run(Recognizer recognizer, Supplier<ActionSelector> selectors, List<Scene> test,
                                       long seed, Replay replay, boolean parallel, Runnable progress) {
        return run(recognizer, selectors, test, seed, replay, parallel, progress, null);
    }

    /**
     * Which stored scene each query's prediction came from: the nearest neighbour holding the
     * selected action (else the nearest), by knowledge-base index, and its distance; -1 and NaN
     * for a query without neighbours.
     *
     * @param index per query, filled by the run
     * @param distance per query, filled by the run
     */
    public record Donors(int[] index, double[] distance) {
        public static Donors of(int queries) {
            int[] index = new int[queries];
            double[] distance = new double[queries];
            Arrays.fill(index, -1);
            Arrays.fill(distance, Double.NaN);
            return new Donors(index, distance);
        }
    }

    /** The same, also filling {@code donors} (null: not wanted) with each query's donor. */
    public static ValidationReport run(Recognizer recognizer, Supplier<ActionSelector> selectors, List<Scene> test,
                                       long seed, Replay replay, boolean parallel, Runnable progress, Donors donors) {
        int n = test.size();
        @SuppressWarnings("unchecked")
        List<Action>[] predicted = new List[n];
        long[] nanos = new long[n];
        ThreadLocal<ActionSelector> selector = ThreadLocal.withInitial(selectors);
        Destinations destinations = replay == Replay.TARGET ? Destinations.of(recognizer.knowledge()) : null;
        IntStream indices = IntStream.range(0, n);
        (parallel ? indices.parallel() : indices).forEach(i -> {
            long start = System.nanoTime();
            try {
                List<Neighbour> nearest = recognizer.nearest(test.get(i));
                Action selected = selector.get().select(nearest, queryRandom(seed, i));
                predicted[i] = prediction(selected, nearest, test.get(i), replay, destinations);
                // no usable action among the neighbours: no prediction, so no donor either
                Neighbour donor = donors == null || selected == null ? null : donor(selected, nearest);
                if (donor != null) {
                    donors.index()[i] = donor.index();
                    donors.distance()[i] = donor.distance();
                }
            } catch (RuntimeException e) {
                // a plugin's or script's error, located by the query it failed on
                throw new QueryFailure(i, test.get(i).cycle(), e);
            }
            nanos[i] = System.nanoTime() - start;
            if (progress != null) {
                progress.run();
            }
        });
        return ValidationReport.of(recognizer.knowledge().scenes(), test, Arrays.asList(predicted), nanos);
    }

    /**
     * The actions a player sends for the selected action ({@link #withNeck}), carried out as
     * {@code replay} says: with {@link Replay#TARGET}, reached from {@code query}'s world model
     * what they achieved in the scene that holds them. A target the player has already reached
     * (a turn to where it faces) gives way to the nearest neighbour's whose target it has not.
     */
    public static List<Action> prediction(Action selected, List<Neighbour> nearest, Scene query, Replay replay) {
        return prediction(selected, nearest, query, replay, null);
    }

    /**
     * The same; with the destinations of the knowledge base the neighbours come from (taken once
     * per run, not per query), a run (dash or turn) steers to the neighbours' mean destination at
     * their mean dash power.
     */
    public static List<Action> prediction(Action selected, List<Neighbour> nearest, Scene query, Replay replay,
                                          Destinations destinations) {
        return prediction(selected, nearest, query, replay, destinations, new Steering());
    }

    /**
     * The same for a player that remembers what its previous decisions chose ({@link Steering}),
     * as a playing agent does from one cycle to the next.
     */
    public static List<Action> prediction(Action selected, List<Neighbour> nearest, Scene query, Replay replay,
                                          Destinations destinations, Steering steering) {
        List<Action> actions = withNeck(selected, nearest);
        if (replay == Replay.RAW || actions.isEmpty()) {
            return actions;
        }
        double[] destination = destinations == null ? null
                : destinations.target(nearest, query.world(), Targets.intercept(query.world()), steering);
        double power = staminaSafe(meanDashPower(nearest), query.world());
        Neighbour donor = donor(actions.get(0), nearest);
        List<Action> reached = Targets.reach(actions, donor == null ? null : donor.scene(), query, destination, power);
        List<Action> chosen = steered(reached, nearest, query, destination, power, steering);
        steering.sent(chosen.isEmpty() ? null : chosen.get(0));
        return chosen;
    }

    /**
     * {@code reached}, unless its turn achieves nothing (the body faces its target already), its
     * kick or tackle cannot reach the ball ({@link Targets#futile}) or its turn goes back against
     * the player's previous turn ({@link Steering}): then the target of the nearest neighbour that
     * does none of these; failing that, the nearest that achieves something; failing that, a run
     * to the ball in place of a futile kick or tackle.
     */
    private static List<Action> steered(List<Action> reached, List<Neighbour> nearest, Scene query,
                                        double[] destination, double power, Steering steering) {
        boolean futile = Targets.futile(reached, query);
        boolean useless = futile || Targets.alreadyReached(reached, query);
        if (!useless && !steering.reverses(reached.get(0))) {
            return reached;
        }
        List<Action> firstUseful = useless ? null : reached;
        for (Neighbour neighbour : nearest) {
            Action other = neighbour.scene().primaryAction();
            if (other != null) {
                List<Action> instead = Targets.reach(withNeck(other, List.of(neighbour)), neighbour.scene(), query,
                        destination, power);
                if (!Targets.alreadyReached(instead, query) && !Targets.futile(instead, query)) {
                    if (!steering.reverses(instead.get(0))) {
                        return instead;
                    }
                    firstUseful = firstUseful == null ? instead : firstUseful;
                }
            }
        }
        if (firstUseful == null && futile) {
            double[] ball = Targets.intercept(query.world());
            if (ball != null) {
                return List.of(Targets.runTo(ball, query.world(), Double.isNaN(power) ? ServerDefaults.MAX_POWER : power));
            }
        }
        return firstUseful == null ? reached : firstUseful;
    }

    /**
     * {@code power}, or less so that a dash leaves the stamina above the level where the server
     * starts to cut the player's effort for good (rcssserver's effort_dec_thr 0.3 of stamina_max
     * 8000): target replay runs every cycle where its teacher paced itself, and its players ended
     * games exhausted. NaN stays NaN unless the stamina asks for less.
     */
    public static double staminaSafe(double power, World world) {
        if (world == null || Double.isNaN(world.stamina())) {
            return power;
        }
        double room = Math.max(0, world.stamina() - STAMINA_FLOOR);
        return Double.isNaN(power) ? (room < ServerDefaults.MAX_POWER ? room : power) : Math.min(power, room);
    }

    /** The stamina a dash should leave: where the effort starts to fall (2,400), and a margin of two cycles' recovery. */
    static final double STAMINA_FLOOR = ServerDefaults.EFFORT_DEC_THR * ServerDefaults.STAMINA_MAX + 100;

    /** The mean power of the neighbours' dashes, NaN when none dashed. */
    private static double meanDashPower(List<Neighbour> nearest) {
        double sum = 0;
        int count = 0;
        for (Neighbour neighbour : nearest) {
            Action action = neighbour.scene().primaryAction();
            if (action != null && action.type() == ActionType.DASH && !Double.isNaN(action.first())) {
                sum += action.first();
                count++;
            }
        }
        return count == 0 ? Double.NaN : sum / count;
    }

    /**
     * The whole prediction for a selected action: selectors pick one action, so the neck action
     * comes from the nearest neighbour whose scene holds the selected action (its other action), or,
     * when none does (a selector that made the action up), from the nearest neighbour's scene.
     */
    public static List<Action> withNeck(Action selected, List<Neighbour> nearest) {
        if (selected == null) {
            return List.of(); // no usable action: none for the body and the neck alike
        }
        Neighbour donor = donor(selected, nearest);
        Action neck = donor == null ? null : ActionLabel.neckAction(donor.scene().actions());
        if (neck == null || neck.equals(selected) || selected.type() == ActionType.TURN_NECK) {
            return List.of(selected);
        }
        return List.of(selected, neck);
    }

    /** The nearest neighbour holding {@code selected}, else the nearest, else null. */
    private static Neighbour donor(Action selected, List<Neighbour> nearest) {
        for (Neighbour neighbour : nearest) {
            if (neighbour.scene().actions().contains(selected)) {
                return neighbour;
            }
        }
        return nearest.isEmpty() ? null : nearest.get(0);
    }

    /** A whole run from a configuration: knowledge base from {@code train}, queries from {@code test}. */
    public static ValidationReport run(KnowledgeBase train, List<Scene> test, MatchConfig config,
                                       PluginRegistry registry, boolean parallel, Runnable progress) {
        return run(train, test, config, registry, parallel, progress, null);
    }

    /** The same, also filling {@code donors} (null: not wanted) with each query's donor. */
    public static ValidationReport run(KnowledgeBase train, List<Scene> test, MatchConfig config,
                                       PluginRegistry registry, boolean parallel, Runnable progress, Donors donors) {
        Recognizer recognizer = config.recognizer(train, registry, config.k());
        return run(recognizer, config.selectorFactory(registry), test, config.seed(), config.replay(), parallel, progress,
                donors);
    }

    /** The generator of query {@code index}: independent of thread and order. */
    public static SplittableRandom queryRandom(long seed, int index) {
        return new SplittableRandom(mix(seed * 0x9E3779B97F4A7C15L + index));
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
