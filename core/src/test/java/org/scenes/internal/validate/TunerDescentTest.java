package org.scenes.internal.validate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** {@link Tuner#descend} with an evaluation of its own, as the Spark tuner plugs one in. */
class TunerDescentTest {
    /** Scores by k and selector; records what it was asked and told ahead. */
    static final class Recording implements Tuner.Evaluation {
        final Map<Integer, Double> byK;
        final List<MatchConfig> scored = new ArrayList<>();
        final List<List<MatchConfig>> ahead = new ArrayList<>();

        Recording(Map<Integer, Double> byK) {
            this.byK = byK;
        }

        @Override
        public double score(MatchConfig config) {
            scored.add(config);
            return byK.get(config.k()) + (config.selector().equals("vote") ? 0.01 : 0);
        }

        @Override
        public void ahead(List<MatchConfig> configurations) {
            ahead.add(configurations);
        }
    }

    static final List<Tuner.Dimension> DIMENSIONS = List.of(
            new Tuner.Dimension("k", List.of(c -> c.withK(1), c -> c.withK(3), c -> c.withK(5))),
            new Tuner.Dimension("selector", List.of(c -> c.withSelector("first-valid", Map.of()),
                    c -> c.withSelector("vote", Map.of()))));

    @Test
    void keepsOnlyStrictlyBetterVariantsAndTellsEachDimensionAhead() {
        // k=3 and k=5 tie: the earlier stays
        Recording evaluation = new Recording(Map.of(1, 0.5, 3, 0.7, 5, 0.7));
        Tuner.Descent descent = Tuner.descend(MatchConfig.DEFAULT, DIMENSIONS, 2, evaluation);
        assertEquals(3, descent.best().k());
        assertEquals("vote", descent.best().selector());
        assertEquals(0.71, descent.score(), 1e-12);
        // the first dimension's variants of the start, then per sweep one list per dimension (the second sweep ends it)
        assertEquals(1 + 2 * DIMENSIONS.size(), evaluation.ahead.size());
        MatchConfig first = MatchConfig.DEFAULT.withK(1);
        assertEquals(List.of(first.withK(1), first.withK(3), first.withK(5)), evaluation.ahead.get(0));
        MatchConfig k3 = first.withK(3);
        assertEquals(List.of(k3.withSelector("first-valid", Map.of()), k3.withSelector("vote", Map.of())),
                evaluation.ahead.get(2), "the selector dimension starts from the best k");
        // 1 start + 3 + 2 in each of the two sweeps
        assertEquals(11, evaluation.scored.size());
    }

    @Test
    void theBuiltInSearchCarriesSideAndPreviousDirectionAcrossMetricVariants() {
        Tuner.Dimension metric = dimension("metric");
        Tuner.Dimension memory = dimension("memory");
        Tuner.Dimension side = dimension("side");
        MatchConfig polar = metric.variants().get(3).apply(MatchConfig.DEFAULT);
        assertEquals("continuous", polar.metric());
        assertEquals("10", polar.metricOptions().get("direction-weight"));
        // memory 0.7 with the previous scene's directions at 0.3 of the current ones: 3 per degree
        MatchConfig remembered = memory.variants().get(5).apply(polar);
        assertEquals("0.7", remembered.metricOptions().get("memory"));
        assertEquals("3", remembered.metricOptions().get("memory-direction-weight"));
        MatchConfig sided = side.variants().get(2).apply(remembered);
        assertEquals("300", sided.metricOptions().get("side-weight"));
        // another polar family keeps both, and plain memory drops the previous direction weight again
        MatchConfig other = metric.variants().get(4).apply(sided);
        assertEquals("300", other.metricOptions().get("side-weight"));
        assertEquals("3", other.metricOptions().get("memory-direction-weight"));
        assertEquals(0.3, other.objectWeights().goal(), 0.0);
        assertEquals(null, memory.variants().get(4).apply(other).metricOptions().get("memory-direction-weight"));
        assertEquals(null, side.variants().get(0).apply(other).metricOptions().get("side-weight"));
        // ball-goal has neither option: the variants leave it as it is
        MatchConfig ballGoal = metric.variants().get(0).apply(sided);
        assertEquals(ballGoal, side.variants().get(3).apply(ballGoal));
        assertEquals(null, ballGoal.metricOptions().get("side-weight"));
        assertEquals(null, ballGoal.metricOptions().get("memory-direction-weight"));
        assertEquals("0.7", ballGoal.metricOptions().get("memory"));
    }

    @Test
    void theGoalsAndRingsVariantsSetTheOwnGoalShareAndTheRingWeight() {
        Tuner.Dimension goals = dimension("goals and rings");
        MatchConfig polar = Tuner.defaultStarts(MatchConfig.DEFAULT).get(1);
        MatchConfig attackedOnly = goals.variants().get(3).apply(polar);
        assertEquals("0", attackedOnly.metricOptions().get("own-goal-weight"));
        assertEquals("3000", attackedOnly.metricOptions().get("row-weight"));
        MatchConfig back = goals.variants().get(0).apply(attackedOnly);
        assertEquals(null, back.metricOptions().get("own-goal-weight"));
        assertEquals("1000", back.metricOptions().get("row-weight"));
        // a polar family without rings stays without them; ball-goal is left as it is
        MatchConfig noRings = dimension("metric").variants().get(2).apply(attackedOnly);
        assertEquals("0", noRings.metricOptions().get("own-goal-weight"), "the metric variant keeps the share");
        assertEquals(null, goals.variants().get(2).apply(noRings).metricOptions().get("row-weight"));
        MatchConfig ballGoal = Tuner.defaultStarts(MatchConfig.DEFAULT).get(0);
        assertEquals(ballGoal, goals.variants().get(3).apply(ballGoal));
    }

    @Test
    void severalStartsKeepTheBestEnd() {
        // scores by k; from k=1 the descent cannot leave (k=3 is worse), from k=5 it reaches k=7
        Map<Integer, Double> byK = Map.of(1, 0.6, 3, 0.5, 5, 0.55, 7, 0.9);
        List<Tuner.Dimension> neighbours = List.of(new Tuner.Dimension("k", List.of(c -> c, c -> c.withK(c.k() == 1 ? 3 : 7))));
        List<MatchConfig> seen = new ArrayList<>();
        Tuner.Descent one = Tuner.descend(MatchConfig.DEFAULT.withK(1), neighbours, 3, config -> byK.get(config.k()));
        assertEquals(1, one.best().k());
        Tuner.Descent both = Tuner.descend(List.of(MatchConfig.DEFAULT.withK(1), MatchConfig.DEFAULT.withK(5)), neighbours, 3,
                config -> {
                    seen.add(config);
                    return byK.get(config.k());
                });
        assertEquals(7, both.best().k());
        assertEquals(0.9, both.score(), 0.0);
        assertEquals(List.of(1, 1, 3, 5, 5, 7, 7, 7), seen.stream().map(MatchConfig::k).toList(),
                "each start descends in turn until a sweep improves nothing");
    }

    private static Tuner.Dimension dimension(String name) {
        return Tuner.defaultSearch().stream().filter(d -> d.name().equals(name)).findFirst().orElseThrow();
    }

    @Test
    void stopsAfterASweepWithoutImprovement() {
        Recording evaluation = new Recording(Map.of(1, 0.9, 3, 0.1, 5, 0.1));
        Tuner.Descent descent = Tuner.descend(MatchConfig.DEFAULT, List.of(DIMENSIONS.get(0)), 5, evaluation);
        assertEquals(1, descent.best().k());
        assertEquals(1 + 3, evaluation.scored.size(), "one sweep, then nothing improved");
    }
}
