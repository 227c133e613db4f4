package org.scenes.plugins.continuous;

import java.util.List;
import java.util.Map;
import org.scenes.api.MetricProvider;
import org.scenes.api.ObjectSetMetrics;
import org.scenes.api.PluginConfig;
import org.scenes.api.SceneMetric;
import org.scenes.api.TuneDimension;

/** {@code continuous}: objects compared by type at their exact positions (docs/metrics.md). */
public final class ContinuousMetricProvider implements MetricProvider {
    @Override
    public String name() {
        return "continuous";
    }

    @Override
    public String description() {
        return "objects matched by type at their seen positions, weighted sum per object class";
    }

    @Override
    public Map<String, String> options() {
        return ObjectSetMetrics.options(false);
    }

    @Override
    public List<TuneDimension> tuneDimensions() {
        return ObjectSetMetrics.tuneDimensions(false);
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        return ObjectSetMetrics.cartesian(config, 0);
    }
}
