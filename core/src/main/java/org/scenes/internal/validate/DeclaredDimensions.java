package org.scenes.internal.validate;

import java.util.Map;
import org.scenes.api.PluginKind;
import org.scenes.api.PluginRegistry;
import org.scenes.api.TuneDimension;

/**
 * What the metrics declare for tuning, as the coordinate descent reads it: which metrics take the
 * object-set variants (the side of the heading, the distance rings, the own goal, the previous
 * scene's directions), and whether a value the descent sets is one its metric declares, so that a
 * provider renaming an option or narrowing its values stops {@code tune} before anything is
 * scored instead of searching something else.
 */
record DeclaredDimensions(PluginRegistry registry) {
    /** The side of the heading: declared by the object-set metrics (continuous, projection, cell) alone. */
    static final String SIDE = "side-weight";
    static final String ROWS = "row-weight";

    /** Whether the configuration's metric is an object-set one: it declares the side of the heading. */
    boolean objectSet(MatchConfig config) {
        return dimensions(config.metric()).containsKey(SIDE);
    }

    /**
     * {@code value} of the metric's {@code option}, as an option text.
     *
     * @throws IllegalStateException when the metric declares no such dimension, or not that value
     */
    String value(String metric, String option, double value) {
        TuneDimension dimension = dimensions(metric).get(option);
        if (dimension == null || !dimension.values().contains(value)) {
            throw new IllegalStateException("tune's descent tries " + option + "=" + Tuner.format(value) + " with the metric "
                    + metric + ", which declares " + (dimension == null ? "no tune dimension of that name (its dimensions: "
                    + dimensions(metric).keySet() + ")" : "only " + dimension.values()));
        }
        return Tuner.format(value);
    }

    /**
     * The configuration, after checking that each of its metric options that the metric declares for
     * tuning has one of the declared values (options it does not declare, such as {@code space}, are
     * the descent's own).
     *
     * @throws IllegalStateException naming the first option and value the metric does not declare
     */
    MatchConfig checked(MatchConfig config) {
        Map<String, TuneDimension> declared = dimensions(config.metric());
        config.metricOptions().forEach((option, text) -> {
            if (declared.containsKey(option)) {
                value(config.metric(), option, Double.parseDouble(text));
            }
        });
        return config;
    }

    private Map<String, TuneDimension> dimensions(String metric) {
        return registry.tuneDimensions(PluginKind.METRIC, metric);
    }
}
