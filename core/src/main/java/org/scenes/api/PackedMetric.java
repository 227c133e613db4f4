package org.scenes.api;

import java.util.List;

/**
 * The fastest path of a {@link SceneMetric}: the whole knowledge base packed once into flat
 * primitive arrays (structure of arrays, no object per scene) and scanned in one pass per query.
 * A packed scan must offer exactly the distances {@link SceneMetric#distance} gives (it may skip
 * scenes whose distance is not below {@link TopK#bound()}), so results never depend on the path.
 */
public interface PackedMetric extends SceneMetric {
    /**
     * @param scenes the knowledge base, in index order
     * @return the packed scenes, or {@code null} when this configuration has no packed form (the
     *         recognizer then uses the other paths)
     */
    PackedScenes pack(List<Scene> scenes);

    /** Packed scenes: read-only once built, so one instance serves every thread. */
    interface PackedScenes {
        /**
         * Offers the distance of every stored scene (by knowledge-base index) that may enter {@code top}.
         *
         * @param query the scene to match
         * @param top receives (distance, index) pairs
         */
        void scan(Scene query, TopK top);
    }
}
