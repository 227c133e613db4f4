package org.scenes.internal.match;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Supplier;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

/** The reference a packed or indexed metric is held to: every distance through the scene-level method. */
final class ExhaustiveScan {
    private ExhaustiveScan() {
    }

    /**
     * Every query against a recognizer on {@code stored} with metrics from {@code tried}, at k = 1, 5, 15:
     * the same indices and bit-identical distances as the exhaustive scan with {@code reference}.
     */
    static void assertRecognizerAgrees(SceneMetric reference, Supplier<SceneMetric> tried, List<Scene> stored,
                                       List<Scene> queries, String about) {
        List<List<Neighbour>> expected = new ArrayList<>();
        for (Scene query : queries) {
            expected.add(neighbours(reference, stored, query));
        }
        for (int k : new int[] {1, 5, 15}) {
            Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), tried, k);
            for (int q = 0; q < queries.size(); q++) {
                List<Neighbour> actual = recognizer.nearest(queries.get(q));
                assertEquals(k, actual.size());
                for (int i = 0; i < k; i++) {
                    String what = "query " + q + ", neighbour " + i + " with " + about + ", k=" + k;
                    assertEquals(expected.get(q).get(i).index(), actual.get(i).index(), what);
                    assertEquals(expected.get(q).get(i).distance(), actual.get(i).distance(), 0.0, what);
                }
            }
        }
    }

    /** Every distance through the scene-level method (no bound), sorted by distance then index. */
    static List<Neighbour> neighbours(SceneMetric metric, List<Scene> stored, Scene query) {
        List<Neighbour> all = new ArrayList<>();
        for (int i = 0; i < stored.size(); i++) {
            all.add(new Neighbour(stored.get(i), i, metric.distance(query, stored.get(i))));
        }
        all.sort(Comparator.comparingDouble(Neighbour::distance).thenComparingInt(Neighbour::index));
        return all;
    }
}
