package org.scenes.api;

import java.util.List;
import java.util.function.Supplier;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * The k stored scenes nearest to a query, among scenes held in memory: the search the imitating
 * agent runs, for tools that study a set of scenes (condensing it, ranking its scenes). It uses
 * the same indexes and fast paths as the agent, so the answers are the agent's.
 */
public final class NearestScenes {
    private final Recognizer recognizer;

    private NearestScenes(Recognizer recognizer) {
        this.recognizer = recognizer;
    }

    /**
     * @param grid the grid the scenes were made with
     * @param scenes the stored scenes, in order (ties go to the earlier one)
     * @param metrics makes one metric per searching thread
     * @param k how many neighbours each search returns, 1 or more
     * @return a search over {@code scenes}
     */
    public static NearestScenes of(Grid grid, List<Scene> scenes, Supplier<SceneMetric> metrics, int k) {
        return new NearestScenes(new Recognizer(KnowledgeBase.of(grid, scenes), metrics, k));
    }

    /**
     * @param query the scene to match
     * @return at most k stored scenes, nearest first
     */
    public List<Neighbour> nearest(Scene query) {
        return recognizer.nearest(query);
    }
}
