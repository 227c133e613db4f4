package org.scenes.properties;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * Properties every metric plugin must have, on scenes jqwik generates: distances never negative
 * or NaN, distance to itself 0 (except {@code random}, which claims nothing), symmetry and the
 * triangle inequality wherever {@link SceneMetric#isTrueMetric()} claims them, and the
 * recognizer's fast paths (ball-goal's index, packed and encoded scans) giving the distances of
 * an exhaustive scan. Every metric is run in several configurations, each its own case.
 */
class MetricPropertiesTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();
    private static final Observer OBSERVER = new Observer("Prop", Side.LEFT, 1);
    private static final Grid GRID = Grid.DEFAULT;

    /** A metric and options: the configurations whose code paths differ. */
    record Case(String metric, Map<String, String> options) {
        SceneMetric create() {
            return REGISTRY.metric(metric, PluginConfig.DEFAULT.withOptions(options));
        }

        boolean deterministic() {
            return !metric.equals("random");
        }

        @Override
        public String toString() {
            return metric + options;
        }
    }

    static final List<Case> CASES = List.of(
            new Case("ball-goal", Map.of()),
            new Case("ball-goal", Map.of("index", "false")),
            new Case("ball-goal", Map.of("angle-weight", "2", "row-weight", "0", "missing", "1")),
            new Case("cell", Map.of()),
            new Case("cell", Map.of("matching", "optimal", "row-weight", "1")),
            new Case("continuous", Map.of()),
            new Case("continuous", Map.of("matching", "optimal")),
            new Case("continuous", Map.of("matching", "optimal", "space", "polar", "log-distance", "true")),
            new Case("continuous", Map.of("matching", "optimal", "penalty", "1000", "penalty-scale", "1000000")),
            new Case("projection", Map.of()),
            new Case("projection", Map.of("matching", "optimal", "cycles", "2")),
            new Case("random", Map.of()));

    @Provide
    Arbitrary<Case> cases() {
        return Arbitraries.of(CASES);
    }

    @Provide
    Arbitrary<Scene> scenes() {
        Arbitrary<List<SeenObject>> flags = object(ObjectKind.FLAG, "f c", Relation.NONE).list().ofMaxSize(4);
        Arbitrary<List<SeenObject>> players = player().list().ofMaxSize(4);
        Arbitrary<List<SeenObject>> ball = object(ObjectKind.BALL, "b", Relation.NONE).list().ofMaxSize(1);
        Arbitrary<List<SeenObject>> goal = object(ObjectKind.GOAL, "g r", Relation.OPPONENT).list().ofMaxSize(1);
        Arbitrary<Action> action = Arbitraries.oneOf(
                Arbitraries.integers().between(-100, 100).map(Action::dash),
                Arbitraries.integers().between(-180, 180).map(Action::turn),
                Arbitraries.integers().between(-90, 90).map(d -> Action.kick(100, d)));
        return Combinators.combine(ball, goal, flags, players, action, Arbitraries.integers().between(0, 6000))
                .as((b, g, f, p, a, cycle) -> {
                    List<SeenObject> objects = new ArrayList<>(b);
                    objects.addAll(g);
                    objects.addAll(f);
                    objects.addAll(p);
                    return new Scene(cycle, OBSERVER, objects, List.of(a));
                });
    }

    private static Arbitrary<Double> distance() {
        // rounded to 0.1 m as the server sends them; near 0 and far both occur
        return Arbitraries.integers().between(1, 1200).map(d -> d / 10.0);
    }

    private static Arbitrary<Double> direction() {
        return Arbitraries.integers().between(-180, 180).map(Integer::doubleValue);
    }

    private static Arbitrary<SeenObject> object(ObjectKind kind, String name, Relation relation) {
        return Combinators.combine(distance(), direction())
                .as((distance, direction) -> SeenObject.simple(kind, name, relation, distance, direction, GRID));
    }

    private static Arbitrary<SeenObject> player() {
        Arbitrary<Relation> relation = Arbitraries.of(Relation.TEAMMATE, Relation.OPPONENT, Relation.UNKNOWN);
        Arbitrary<Double> change = Arbitraries.integers().between(-30, 30).map(c -> c / 10.0);
        return Combinators.combine(relation, distance(), direction(), change)
                .as((r, distance, direction, c) -> new SeenObject(ObjectKind.PLAYER, "p", "", 0, false, r, distance,
                        direction, c, -c, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, GRID.cell(distance, direction)));
    }

    @Provide
    Arbitrary<List<Scene>> knowledge() {
        return scenes().list().ofMinSize(1).ofMaxSize(40);
    }

    @Example
    void theSymmetryAndTrianglePropertiesHaveTrueMetricsToCheck() {
        // else the two properties below would pass without checking anything
        List<String> claimed = CASES.stream().filter(c -> c.create().isTrueMetric()).map(Case::toString).toList();
        assertTrue(claimed.size() >= 3, claimed.toString());
    }

    @Property(tries = 300)
    void distancesAreNeverNegativeOrNaN(@ForAll("cases") Case metricCase, @ForAll("scenes") Scene a, @ForAll("scenes") Scene b) {
        double distance = metricCase.create().distance(a, b);
        assertFalse(Double.isNaN(distance), metricCase + ": NaN");
        assertTrue(distance >= 0, metricCase + ": " + distance);
    }

    @Property(tries = 300)
    void theDistanceToItselfIsZero(@ForAll("cases") Case metricCase, @ForAll("scenes") Scene a) {
        if (metricCase.deterministic()) {
            assertEquals(0.0, metricCase.create().distance(a, a), 1e-9, metricCase.toString());
        }
    }

    @Property(tries = 300)
    void trueMetricsAreSymmetric(@ForAll("cases") Case metricCase, @ForAll("scenes") Scene a, @ForAll("scenes") Scene b) {
        SceneMetric metric = metricCase.create();
        if (metric.isTrueMetric()) {
            double ab = metric.distance(a, b);
            assertEquals(ab, metric.distance(b, a), 1e-9 * (1 + ab), metricCase.toString());
        }
    }

    @Property(tries = 400)
    void trueMetricsObeyTheTriangleInequality(@ForAll("cases") Case metricCase, @ForAll("scenes") Scene a,
                                              @ForAll("scenes") Scene b, @ForAll("scenes") Scene c) {
        SceneMetric metric = metricCase.create();
        if (metric.isTrueMetric()) {
            double ac = metric.distance(a, c);
            double viaB = metric.distance(a, b) + metric.distance(b, c);
            assertTrue(ac <= viaB + 1e-9 * (1 + viaB), metricCase + ": d(a,c) " + ac + " > d(a,b) + d(b,c) " + viaB);
        }
    }

    @Property(tries = 150)
    void theRecognizerFindsTheDistancesOfAnExhaustiveScan(@ForAll("cases") Case metricCase,
                                                          @ForAll("knowledge") List<Scene> stored,
                                                          @ForAll("scenes") Scene query,
                                                          @ForAll @IntRange(min = 1, max = 8) int k) {
        if (!metricCase.deterministic()) {
            return;
        }
        SceneMetric exhaustive = metricCase.create();
        List<Double> expected = new ArrayList<>();
        for (Scene scene : stored) {
            expected.add(exhaustive.distance(query, scene));
        }
        List<Double> sorted = expected.stream().sorted(Comparator.naturalOrder()).toList();
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(GRID, stored), metricCase::create, k);
        List<Neighbour> found = recognizer.nearest(query);
        assertEquals(Math.min(k, stored.size()), found.size(), metricCase.toString());
        for (int i = 0; i < found.size(); i++) {
            Neighbour neighbour = found.get(i);
            String what = metricCase + ", neighbour " + i + " of k=" + k + " among " + stored.size();
            // the i-th nearest distance, and the scene it names is at that distance
            assertEquals(sorted.get(i), neighbour.distance(), 1e-9 * (1 + sorted.get(i)), what);
            assertEquals(expected.get(neighbour.index()), neighbour.distance(), 1e-9 * (1 + neighbour.distance()), what);
        }
    }
}
