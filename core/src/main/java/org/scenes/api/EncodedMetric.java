package org.scenes.api;

/**
 * The fast path of a {@link SceneMetric}: each scene is turned once into a compact encoding
 * (arrays of numbers), and distances are computed between encodings. The recognizer encodes
 * the knowledge base once and each query once, so the per-pair work is arithmetic only.
 * {@link #distance(Object, Object, double)} may stop early and return any value above
 * {@code bound} once the distance is known to exceed it (early abandoning).
 *
 * @param <E> the encoding; must be safe to read from several threads once built
 */
public interface EncodedMetric<E> extends SceneMetric {
    /**
     * @param scene any scene
     * @return its encoding, computed once per scene
     */
    E encode(Scene scene);

    /**
     * @param query the encoded query
     * @param stored an encoded stored scene
     * @param bound the largest distance the caller still cares about ({@code +Infinity} for any)
     * @return the exact distance when it is at most {@code bound}, otherwise any value above it
     */
    double distance(E query, E stored, double bound);

    @Override
    default double distance(Scene query, Scene stored) {
        return distance(encode(query), encode(stored), Double.POSITIVE_INFINITY);
    }
}
