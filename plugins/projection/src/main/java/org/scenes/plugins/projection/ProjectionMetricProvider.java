package org.scenes.plugins.projection;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.MetricProvider;
import org.scenes.api.ObjectSetMetrics;
import org.scenes.api.PluginConfig;
import org.scenes.api.SceneMetric;
import org.scenes.api.TuneDimension;

/**
 * {@code projection}: like {@code continuous}, but each object is first moved n cycles forward
 * (or back) by the distance and direction change the server reported for it, so scenes are
 * compared as they will look (or looked) rather than as they are.
 */
public final class ProjectionMetricProvider implements MetricProvider {
    @Override
    public String name() {
        return "projection";
    }

    @Override
    public String description() {
        return "continuous matching after projecting objects n cycles by their distance/direction change";
    }

    @Override
    public Map<String, String> options() {
        Map<String, String> options = new LinkedHashMap<>(ObjectSetMetrics.options(true));
        options.put("space", "cartesian or polar (default cartesian)");
        return options;
    }

    @Override
    public List<TuneDimension> tuneDimensions() {
        return ObjectSetMetrics.tuneDimensions(true);
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        return ObjectSetMetrics.cartesian(config, 1);
    }
}
