package org.scenes.cli;

import java.util.List;
import java.util.Map;
import org.scenes.api.PluginRegistry;
import org.scenes.coverage.KeyScenes;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.validate.MatchConfig;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/** The options of {@code --key-scenes N} shared by show and export (a mixin): by influence (with a metric) or by events. */
final class KeySceneChoice {
    /** How key scenes are chosen, by the name {@code --key-by} takes. */
    enum KeyBy {
        /** the scenes whose neighbours' predictions hang on them most, most first */
        INFLUENCE("influence"),
        /** the first N events (kicks, moves, the ball changing hands), in order */
        EVENTS("events");

        private final String key;

        KeyBy(String key) {
            this.key = key;
        }

        String key() {
            return key;
        }
    }

    static final class KeyByConverter implements ITypeConverter<KeyBy> {
        @Override
        public KeyBy convert(String value) {
            for (KeyBy keyBy : KeyBy.values()) {
                if (keyBy.key.equals(value)) {
                    return keyBy;
                }
            }
            throw new TypeConversionException("expected influence or events, not '" + value + "'");
        }
    }

    @Option(names = "--key-by", paramLabel = "influence|events", defaultValue = "influence", converter = KeyByConverter.class,
            description = "--key-scenes by influence on neighbours' predictions (default) or the first N events (kicks,"
                    + " moves, the ball changing hands).")
    KeyBy keyBy = KeyBy.INFLUENCE;

    @Option(names = "--metric", paramLabel = "NAME", description = "The metric ranking --key-scenes (default: the default configuration's).")
    String metric;

    /** The N key scenes of one file, most first (influence) or in order (events). */
    List<KeyScenes.Ranked> choose(SceneFile scenes, int count, PluginRegistry registry) {
        check(count);
        if (keyBy == KeyBy.EVENTS) {
            return KeyScenes.events(scenes.scenes(), count);
        }
        MatchConfig config = metric == null ? MatchConfig.DEFAULT : MatchConfig.DEFAULT.withMetric(metric, Map.of());
        config.check(registry);
        return KeyScenes.rank(scenes.grid(), scenes.scenes(), config.metricFactory(registry), count);
    }

    static void check(int count) {
        if (count < 1) {
            throw new UsageException("--key-scenes must be at least 1, not " + count);
        }
    }
}
