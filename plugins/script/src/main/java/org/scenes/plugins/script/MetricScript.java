package org.scenes.plugins.script;

import groovy.lang.Script;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

/**
 * Base class of every metric script. A script file becomes a subclass whose top-level methods
 * are the metric, in one of two forms:
 * <ul>
 *   <li>simple: {@code double distance(Scene query, Scene stored)};</li>
 *   <li>fast: {@code double[] encode(Scene scene)} and
 *       {@code double distance(double[] query, double[] stored, double bound)}, like a Java
 *       {@link org.scenes.api.EncodedMetric EncodedMetric&lt;double[]&gt;}: the recognizer encodes
 *       every scene once and compares arrays.</li>
 * </ul>
 * Statements outside methods run once when the metric is created (after {@link #getConfig()}
 * is set), so they can prepare state kept in {@code @Field} variables.
 */
public abstract class MetricScript extends Script implements SceneMetric {
    private PluginConfig config = PluginConfig.DEFAULT;

    /** Everything the metric was configured with (object weights, seed, options). */
    public PluginConfig getConfig() {
        return config;
    }

    /** The object weights of the run, in the thesis' order. */
    public ObjectWeights getWeights() {
        return config.objectWeights();
    }

    final void configure(PluginConfig newConfig) {
        this.config = newConfig;
    }

    /** The simple form, from the fast one when the script defines that instead. */
    @Override
    public double distance(Scene query, Scene stored) {
        return distance(encode(query), encode(stored), Double.POSITIVE_INFINITY);
    }

    /** The fast form's encoding; a script using the fast form defines it. */
    public double[] encode(Scene scene) {
        throw new UnsupportedOperationException("this metric script has no encode(Scene) method");
    }

    /**
     * The fast form's distance between two encodings. It may stop early and return any value
     * above {@code bound} once the distance is known to exceed it.
     */
    public double distance(double[] query, double[] stored, double bound) {
        throw new UnsupportedOperationException("this metric script has no distance(double[], double[], double) method");
    }

    /** Whether the script defines the fast form (checked once, when the metric is created). */
    final boolean encodes() {
        try {
            getClass().getDeclaredMethod("encode", Scene.class);
            getClass().getDeclaredMethod("distance", double[].class, double[].class, double.class);
            return true;
        } catch (NoSuchMethodException e) {
            return false;
        }
    }
}
