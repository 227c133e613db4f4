package org.scenes.match;

import org.scenes.scene.Scene;

/**
 * Rewrites scenes before matching, e.g. adding remembered objects or mirroring. A transform
 * sees the scenes of one player in order and may keep state between them; create a new one
 * for each sequence (each scene file, each game).
 */
public interface SceneTransform {
    Scene apply(Scene scene);
}
