package org.scenes.api;

import java.util.List;
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
        public List<TuneDimension> tuneDimensions() {
            return List.of(TuneDimension.log("scale", 0, 1, 10));
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

    /** Declares a tune dimension that is none of its options: loading it must fail. */
    public static final class Misdeclared extends Counting {
        @Override
        public String name() {
            return "misdeclared";
        }

        @Override
        public List<TuneDimension> tuneDimensions() {
            return List.of(TuneDimension.log("scal", 1, 10));
        }
    }

    /** Same name as {@link Counting}: loading both must fail. */
    public static final class CountingTwin extends Counting {
    }
}
