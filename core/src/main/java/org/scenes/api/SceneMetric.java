package org.scenes.api;

/**
 * Distance between two scenes; lower is closer, 0 for scenes the metric cannot tell apart.
 * Implementations may keep per-query state but must be usable from one thread at a time;
 * the recognizer creates one instance per thread.
 */
public interface SceneMetric {
    double distance(Scene query, Scene stored);

    /**
     * Whether this is a true metric: symmetric, zero on identical scenes and obeying the
     * triangle inequality. Search indexes may prune with it only when true.
     */
    default boolean isTrueMetric() {
        return false;
    }
}
