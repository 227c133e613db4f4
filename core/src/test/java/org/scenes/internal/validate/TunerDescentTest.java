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

    @Test
    void stopsAfterASweepWithoutImprovement() {
        Recording evaluation = new Recording(Map.of(1, 0.9, 3, 0.1, 5, 0.1));
        Tuner.Descent descent = Tuner.descend(MatchConfig.DEFAULT, List.of(DIMENSIONS.get(0)), 5, evaluation);
        assertEquals(1, descent.best().k());
        assertEquals(1 + 3, evaluation.scored.size(), "one sweep, then nothing improved");
    }
}
