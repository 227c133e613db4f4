package org.scenes.plugins.cell;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.MetricProvider;
import org.scenes.api.ObjectSetMetrics;
import org.scenes.api.PluginConfig;
import org.scenes.api.SceneMetric;
import org.scenes.api.TuneDimension;

/** {@code cell}: objects compared by type at the grid cells they fall in (docs/metrics.md). */
public final class CellMetricProvider implements MetricProvider {
    @Override
    public String name() {
        return "cell";
    }

    @Override
    public String description() {
        return "objects matched by type at their grid cells (column, row), weighted sum per object class";
    }

    @Override
    public Map<String, String> options() {
        Map<String, String> options = new LinkedHashMap<>(ObjectSetMetrics.options(false));
        options.remove("space");
        options.remove("log-distance");
        options.remove("distance-weight");
        options.remove("direction-weight");
        options.put("penalty", "cost of an unmatched object in the nearest row (default 1)");
        options.put("penalty-scale", "row at which the unmatched penalty halves (default 1)");
        return options;
    }

    /** The side of the heading, the rings and the unmatched penalty, in rows: cell compares no positions. */
    @Override
    public List<TuneDimension> tuneDimensions() {
        return List.of(TuneDimension.log("side-weight", 30, 100, 300, 1000),
                TuneDimension.log("row-weight", 0, 10, 100, 1000, 1000, 3000),
                TuneDimension.log("penalty", 1, 10, 100),
                TuneDimension.log("penalty-scale", 1, 3));
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        Map<String, String> options = new LinkedHashMap<>(config.options());
        options.putIfAbsent("penalty", "1");
        options.putIfAbsent("penalty-scale", "1");
        return ObjectSetMetrics.cells(config.withOptions(options));
    }
}
