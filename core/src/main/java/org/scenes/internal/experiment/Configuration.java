package org.scenes.internal.experiment;

import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;

/**
 * One point of a sweep: everything that decides a validation's numbers besides the data,
 * the folds and the seed, which the whole sweep shares.
 */
public record Configuration(String metric, ObjectWeights weights, int k, String selector, ActionWeights actionWeights) {
    public Configuration {
        if (k < 1) {
            throw new IllegalArgumentException("k must be at least 1, not " + k);
        }
    }

    /** This configuration's value on an axis, as tables show it. */
    public String value(Axis axis) {
        return switch (axis) {
            case METRIC -> metric;
            case WEIGHTS -> weights.format();
            case K -> Integer.toString(k);
            case SELECTOR -> selector;
            case ACTION_WEIGHTS -> actionWeights.format();
        };
    }
}
