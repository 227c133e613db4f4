package org.scenes.api;

import java.util.List;
import java.util.function.UnaryOperator;
import org.scenes.internal.match.Recognizer;

/**
 * Rewrites scenes before matching, e.g. adding remembered objects or mirroring. A transform
 * sees the scenes of one player in order and may keep state between them; create a new one
 * for each sequence (each scene file, each game).
 */
public interface SceneTransform {
    /**
     * @param scene the next scene of the sequence
     * @return the scene to match (or store) instead; {@code scene} itself when nothing changes
     */
    Scene apply(Scene scene);

    /**
     * The scenes a knowledge base stores for {@code scene}: by default {@link #apply} alone. A
     * transform that adds scenes (the mirror image of each) returns several, while queries still
     * go through {@link #apply}.
     *
     * @param scene the next scene of the sequence
     * @return the scenes to store, at least one
     */
    default List<Scene> stored(Scene scene) {
        return List.of(apply(scene));
    }

    /**
     * A transform that matches each query in a second orientation too (rather than storing the
     * scenes in both) returns the map to it, an involution such as the mirror image, applied to
     * the fully transformed query; the {@link Recognizer} then returns scenes found for the image
     * as their own images. Default: null, one orientation.
     *
     * @return the map to the second orientation, or null
     */
    default UnaryOperator<Scene> queryImage() {
        return null;
    }

    /**
     * The one query image of a sequence's transforms, or null; two are refused (they would undo each other).
     *
     * @param transforms the transforms, in the order they apply
     * @return the one non-null {@link #queryImage()}, or null
     */
    static UnaryOperator<Scene> queryImage(List<SceneTransform> transforms) {
        UnaryOperator<Scene> found = null;
        for (SceneTransform transform : transforms) {
            UnaryOperator<Scene> image = transform.queryImage();
            if (image != null && found != null) {
                throw new IllegalArgumentException("only one transform may match queries in a second orientation");
            }
            found = image != null ? image : found;
        }
        return found;
    }
}
