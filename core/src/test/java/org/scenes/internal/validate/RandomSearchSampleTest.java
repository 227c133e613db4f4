package org.scenes.internal.validate;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.scenes.api.ActionType;
import org.scenes.api.Scene;
import org.scenes.internal.match.TestScenes;

class RandomSearchSampleTest {
    /** Krislet-like: dashes and turns alternate in runs, kicks are rare and off any stride. */
    private static final Set<Integer> KICKS = Set.of(7, 800, 1201, 2003, 2999);

    private static List<Scene> fold() {
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            double distance = KICKS.contains(i) ? 0.5 : 10;
            double direction = KICKS.contains(i) || (i / 13) % 3 == 0 ? 0 : 15;
            scenes.add(TestScenes.krislet(i, distance, direction, 5));
        }
        return scenes;
    }

    private static Map<ActionType, Integer> counts(List<Scene> scenes, int[] positions) {
        Map<ActionType, Integer> counts = new EnumMap<>(ActionType.class);
        for (int i : positions) {
            counts.merge(scenes.get(i).actionType(), 1, Integer::sum);
        }
        return counts;
    }

    @Test
    void everyActionTypeOfTheFoldIsInEverySample() {
        List<Scene> scenes = fold();
        Map<ActionType, Integer> all = counts(scenes, IntStream.range(0, scenes.size()).toArray());
        assertEquals(Set.of(ActionType.DASH, ActionType.TURN, ActionType.KICK), all.keySet());
        for (int stride : new int[] {3, 9, 27, 81}) {
            int[] sample = RandomSearch.sample(scenes, stride);
            Map<ActionType, Integer> sampled = counts(scenes, sample);
            assertEquals(all.keySet(), sampled.keySet(), "stride " + stride);
            // fewer kicks than the minimum: all of them
            assertEquals(KICKS.size(), sampled.get(ActionType.KICK), "stride " + stride);
            for (ActionType common : new ActionType[] {ActionType.DASH, ActionType.TURN}) {
                assertEquals((all.get(common) + stride - 1) / stride, sampled.get(common), common + " at stride " + stride);
            }
            for (int q = 1; q < sample.length; q++) {
                assertTrue(sample[q - 1] < sample[q], "ascending and distinct");
            }
        }
    }

    @Test
    void aPlainStrideWouldMissTheKicks() {
        List<Scene> scenes = fold();
        // the sampling this replaces: every 27th scene holds none of the five kicks
        assertTrue(IntStream.range(0, scenes.size()).filter(i -> i % 27 == 0).noneMatch(KICKS::contains));
        assertTrue(IntStream.of(RandomSearch.sample(scenes, 27)).boxed().toList().containsAll(KICKS));
    }

    @Test
    void strideOneIsEveryScene() {
        List<Scene> scenes = fold();
        assertArrayEquals(IntStream.range(0, scenes.size()).toArray(), RandomSearch.sample(scenes, 1));
    }
}
