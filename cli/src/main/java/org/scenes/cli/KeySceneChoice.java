package org.scenes.cli;

import java.util.List;
import java.util.Map;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.plugins.coverage.KeyScenes;

/** The options of {@code --key-scenes N} shared by show and export: by influence (with a metric) or by events. */
final class KeySceneChoice {
    private KeySceneChoice() {
    }

    /** The N key scenes of one file, most first (influence) or in order (events). */
    static List<KeyScenes.Ranked> choose(SceneFile scenes, int count, String keyBy, String metric, PluginRegistry registry) {
        check(count, keyBy);
        if (keyBy.equals("events")) {
            return KeyScenes.events(scenes.scenes(), count);
        }
        MatchConfig config = metric == null ? MatchConfig.DEFAULT : MatchConfig.DEFAULT.withMetric(metric, Map.of());
        config.check(registry);
        return KeyScenes.rank(scenes.grid(), scenes.scenes(), config.metricFactory(registry), count);
    }

    static void check(int count, String keyBy) {
        if (count < 1) {
            throw new UsageException("--key-scenes must be at least 1, not " + count);
        }
        if (!keyBy.equals("influence") && !keyBy.equals("events")) {
            throw new UsageException("--key-by must be influence or events, not " + keyBy);
        }
    }
}
