package org.scenes.match;

import org.scenes.scene.Scene;

/**
 * Rewrites scenes before matching, e.g. adding remembered objects or mirroring. A transform
 * sees the scenes of one player in order and may keep state between them; create a new one
 * for each sequence (each scene file, each game).
 */
public interface SceneTransform {
    Scene apply(Scene scene);

    /**
     * The scenes a knowledge base stores for {@code scene}: by default {@link #apply} alone. A
     * transform that adds scenes (the mirror image of each) returns several, while queries still
     * go through {@link #apply}.
     */
    default java.util.List<Scene> stored(Scene scene) {
        return java.util.List.of(apply(scene));
    }
}
