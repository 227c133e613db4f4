package org.scenes.internal.experiment;

import java.util.Locale;

/** A dimension a sweep varies, and the name tables, files and sweep scripts use for it. */
public enum Axis {
    METRIC("metric"),
    WEIGHTS("weights"),
    K("k"),
    SELECTOR("selector"),
    ACTION_WEIGHTS("action-weights");

    private final String key;

    Axis(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    public static Axis fromKey(String key) {
        for (Axis axis : values()) {
            if (axis.key.equals(key.toLowerCase(Locale.ROOT))) {
                return axis;
            }
        }
        throw new IllegalArgumentException("unknown sweep axis '" + key + "'; axes: metric, weights, k, selector, action-weights");
    }
}
