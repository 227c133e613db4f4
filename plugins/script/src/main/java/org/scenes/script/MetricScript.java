package org.scenes.script;

import groovy.lang.Script;
import org.scenes.match.ObjectWeights;
import org.scenes.match.SceneMetric;
import org.scenes.plugin.PluginConfig;

/**
 * Base class of every metric script: a script file becomes a subclass whose top-level
 * {@code double distance(Scene query, Scene stored)} method is the metric. Statements outside
 * methods run once when the metric is created (after {@link #getConfig()} is set), so they can
 * prepare state kept in {@code @Field} variables.
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
}
