package org.scenes.api;

/**
 * Distance between two scenes; lower is closer, 0 for scenes the metric cannot tell apart.
 * Implementations may keep per-query state but must be usable from one thread at a time;
 * the recognizer creates one instance per thread.
 */
public interface SceneMetric {
    /**
     * @param query the scene the agent sees now
     * @param stored a scene of the knowledge base
     * @return the distance, 0 or more; lower is closer
     */
    double distance(Scene query, Scene stored);

    /**
     * Whether this is a true metric: symmetric, zero on identical scenes and obeying the
     * triangle inequality. Search indexes may prune with it only when true.
     *
     * @return false unless all three properties hold
     */
    default boolean isTrueMetric() {
        return false;
    }
}
