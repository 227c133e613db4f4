package org.scenes.plugins.script;

import groovy.lang.Script;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionWeights;
import org.scenes.api.PluginConfig;

/**
 * Base class of every selector script: a script file becomes a subclass whose top-level
 * {@code Action select(List<Neighbour> nearest, RandomGenerator random)} method is the
 * selector. Statements outside methods run once when the selector is created.
 */
public abstract class SelectorScript extends Script implements ActionSelector {
    private PluginConfig config = PluginConfig.DEFAULT;

    /** Everything the selector was configured with (action weights, seed, options). */
    public PluginConfig getConfig() {
        return config;
    }

    /** The action weights of the run, in the thesis' order. */
    public ActionWeights getActionWeights() {
        return config.actionWeights();
    }

    final void configure(PluginConfig newConfig) {
        this.config = newConfig;
    }
}
