package org.scenes.plugins.random;

import org.scenes.api.Action;
import org.scenes.api.EncodedMetric;
import org.scenes.api.MetricProvider;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

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
            return mix(seed ^ contentHash(scene));
        }

        /** A hash of what the scene holds that, unlike enum and record hash codes, is the same in every JVM run. */
        static long contentHash(Scene scene) {
            long hash = scene.cycle();
            hash = hash * 31 + scene.observer().team().hashCode();
            hash = hash * 31 + scene.observer().uniformNumber();
            for (SeenObject object : scene.objects()) {
                hash = hash * 31 + object.kind().ordinal();
                hash = hash * 31 + object.name().hashCode();
                hash = hash * 31 + object.relation().ordinal();
                hash = hash * 31 + Double.hashCode(object.distance());
                hash = hash * 31 + Double.hashCode(object.direction());
            }
            for (Action action : scene.actions()) {
                hash = hash * 31 + action.type().ordinal();
                hash = hash * 31 + Double.hashCode(action.first());
                hash = hash * 31 + Double.hashCode(action.second());
            }
            return hash;
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
