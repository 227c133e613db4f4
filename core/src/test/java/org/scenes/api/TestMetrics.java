package org.scenes.api;

import java.util.Map;

/** Metric providers on the test class path, registered in META-INF/services. */
final class TestMetrics {
    private TestMetrics() {
    }

    /** Distance = number of objects in the stored scene times the "scale" option. */
    public static class Counting implements MetricProvider {
        @Override
        public String name() {
            return "counting";
        }

        @Override
        public String description() {
            return "counts the stored scene's objects";
        }

        @Override
        public Map<String, String> options() {
            return Map.of("scale", "multiplies the count");
        }

        @Override
        public SceneMetric create(PluginConfig config) {
            double scale = config.doubleOption("scale", 1);
            return (query, stored) -> scale * stored.objects().size();
        }
    }

    /** Hands its argument back as the distance, to show {@code name:argument} specs. */
    public static final class Constant implements MetricProvider {
        @Override
        public String name() {
            return "constant";
        }

        @Override
        public String description() {
            return "returns the number after the colon";
        }

        @Override
        public SceneMetric create(PluginConfig config) {
            double value = Double.parseDouble(config.argument());
            return (query, stored) -> value;
        }
    }

    /** Same name as {@link Counting}: loading both must fail. */
    public static final class CountingTwin extends Counting {
    }
}
