package org.scenes.plugins.random;

import org.scenes.match.EncodedMetric;
import org.scenes.match.MetricProvider;
import org.scenes.match.SceneMetric;
import org.scenes.plugin.PluginConfig;
import org.scenes.scene.Scene;

/** {@code random}: distances drawn at random, so the nearest scene is a random one: the statistical floor. */
public final class RandomMetricProvider implements MetricProvider {
    @Override
    public String name() {
        return "random";
    }

    @Override
    public String description() {
        return "random distances: picks stored scenes at random (the floor to beat)";
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        return new RandomMetric(config.seed());
    }

    /**
     * The distance of a pair is a hash of the seed and both scenes' contents, so it is random
     * but repeatable, and the same whatever thread or order asks.
     */
    static final class RandomMetric implements EncodedMetric<Long> {
        private final long seed;

        RandomMetric(long seed) {
            this.seed = seed;
        }

        @Override
        public Long encode(Scene scene) {
            return mix(seed ^ scene.hashCode());
        }

        @Override
        public double distance(Long query, Long stored, double bound) {
            return (mix(query * 31 + stored) >>> 11) * 0x1.0p-53;
        }

        private static long mix(long z) {
            z = (z ^ (z >>> 33)) * 0xff51afd7ed558ccdL;
            z = (z ^ (z >>> 33)) * 0xc4ceb9fe1a85ec53L;
            return z ^ (z >>> 33);
        }
    }
}
