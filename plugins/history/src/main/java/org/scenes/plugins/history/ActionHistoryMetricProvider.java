package org.scenes.plugins.history;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.MetricProvider;
import org.scenes.api.PackedMetric;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.TopK;

/**
 * {@code action-history}: scenes are near when the player did the same things before them and
 * sees the ball alike. Made for agents that act every cycle on synchronous vision (HELIOS base):
 * their next body action follows mostly from the plan under way, which the last few actions
 * (class, the size of the last one) and the see age show, and the ball tells the rest.
 *
 * <pre>
 * d = age · [age differs]
 *   + Σ_i decay^(i-1) · (class · [body class i back differs] + age-history · [see age i back differs]
 *                        + neck · [neck class i back differs])        i = 1 .. depth
 *   + magnitude · |size of the last action − its size|                (turn |moment| / 180, dash or kick power / 100)
 *   + ball terms: ball-distance · |ln(1 + r) − ln(1 + r')| + ball-direction · |θ − θ'| / 180
 *                 + ball-change · |Δr − Δr'|, or ball-missing when only one scene sees the ball
 * </pre>
 *
 * Needs the {@code history} transform (without it every scene has an empty past).
 */
public final class ActionHistoryMetricProvider implements MetricProvider {
    static final Map<String, Double> DEFAULTS = defaults();

    private static Map<String, Double> defaults() {
        Map<String, Double> defaults = new LinkedHashMap<>();
        defaults.put("depth", 4.0);
        defaults.put("class", 16.0);
        defaults.put("decay", 0.5);
        defaults.put("age", 8.0);
        defaults.put("age-history", 1.0);
        defaults.put("neck", 1.0);
        defaults.put("magnitude", 4.0);
        defaults.put("ball-distance", 1.0);
        defaults.put("ball-direction", 1.0);
        defaults.put("ball-change", 1.0);
        defaults.put("ball-missing", 2.0);
        return Map.copyOf(defaults);
    }

    @Override
    public String name() {
        return "action-history";
    }

    @Override
    public String description() {
        return "the last actions' classes and see ages, the last action's size and the ball (needs the history transform)";
    }

    @Override
    public Map<String, String> options() {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("depth", "how many earlier scenes count, 0 to " + Scene.MAX_MEMORY + " (default 4)");
        options.put("class", "cost when the body classes one scene back differ (default 16); i back costs decay^(i-1) of it");
        options.put("decay", "factor of each further step back (default 0.5)");
        options.put("age", "cost when the see ages differ (default 8)");
        options.put("age-history", "cost when the see ages one scene back differ (default 1)");
        options.put("neck", "cost when the neck classes one scene back differ (default 1)");
        options.put("magnitude", "cost per unit of the last action's size: |turn moment| / 180, dash or kick power / 100 (default 4)");
        options.put("ball-distance", "cost per unit of ln(1 + ball distance) (default 1)");
        options.put("ball-direction", "cost per 180 degrees of ball direction (default 1)");
        options.put("ball-change", "cost per metre of the ball's distance change (default 1)");
        options.put("ball-missing", "cost when only one scene sees the ball (default 2)");
        return options;
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        Map<String, Double> values = new LinkedHashMap<>();
        for (Map.Entry<String, Double> entry : DEFAULTS.entrySet()) {
            double value = config.doubleOption(entry.getKey(), entry.getValue());
            if (!(value >= 0) || Double.isInfinite(value)) {
                throw new PluginException("action-history option " + entry.getKey() + " must be finite and not negative, not "
                        + config.option(entry.getKey(), ""));
            }
            values.put(entry.getKey(), value);
        }
        double depth = values.get("depth");
        if (depth != Math.rint(depth) || depth > Scene.MAX_MEMORY) {
            throw new PluginException("action-history option depth must be a whole number from 0 to " + Scene.MAX_MEMORY
                    + ", not " + config.option("depth", ""));
        }
        return new ActionHistoryMetric(new HistoryFeatures(values));
    }

    /** Scenes are packed once into their feature vectors; both paths share one distance routine. */
    static final class ActionHistoryMetric implements PackedMetric {
        private final HistoryFeatures features;

        ActionHistoryMetric(HistoryFeatures features) {
            this.features = features;
        }

        @Override
        public double distance(Scene query, Scene stored) {
            return features.distance(features.encode(query), 0, features.encode(stored), 0);
        }

        @Override
        public PackedScenes pack(List<Scene> scenes) {
            int width = features.width();
            double[] packed = new double[scenes.size() * width];
            for (int i = 0; i < scenes.size(); i++) {
                System.arraycopy(features.encode(scenes.get(i)), 0, packed, i * width, width);
            }
            int count = scenes.size();
            return (query, top) -> scan(features.encode(query), packed, count, top);
        }

        private void scan(double[] query, double[] packed, int count, TopK top) {
            int width = features.width();
            for (int i = 0, offset = 0; i < count; i++, offset += width) {
                double bound = top.bound();
                double distance = features.distance(query, 0, packed, offset, bound);
                if (distance < bound) {
                    top.offer(distance, i);
                }
            }
        }
    }
}
