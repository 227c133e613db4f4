package org.scenes.options;

import java.util.function.Function;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.Tuner;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * The converters of options whose values are enum constants, each read by the key results and
 * scripts write ({@code leave-one-out}, {@code macro-f1}): one parser per option value, in every
 * command that takes it. A bad value is picocli's usage error, naming the option.
 */
public final class KeyConverters {
    private KeyConverters() {
    }

    private static <E> E convert(String value, Function<String, E> fromKey, String keys) {
        E constant = fromKey.apply(value);
        if (constant == null) {
            throw new TypeConversionException("expected " + keys + ", not '" + value + "'");
        }
        return constant;
    }

    /**
     * {@code --protocol next|leave-one-out}. Its one default rule: {@code validate --folds} trains on
     * the next file (the thesis' protocol, so its figures compare with the thesis'); {@code tune}
     * trains on all other files (closest to training on the whole game, which the tuned configuration
     * will do).
     */
    public static final class Protocol implements ITypeConverter<Folds.Protocol> {
        @Override
        public Folds.Protocol convert(String value) {
            return KeyConverters.convert(value, Folds.Protocol::fromKey, Folds.Protocol.keys());
        }
    }

    /** {@code --objective mean|accuracy|direction|macro-f1}. */
    public static final class Objective implements ITypeConverter<Tuner.Objective> {
        @Override
        public Tuner.Objective convert(String value) {
            return KeyConverters.convert(value, Tuner.Objective::fromKey, "mean, accuracy, direction or macro-f1");
        }
    }

    /** {@code --replay raw|target}. */
    public static final class Replay implements ITypeConverter<org.scenes.internal.target.Replay> {
        @Override
        public org.scenes.internal.target.Replay convert(String value) {
            return KeyConverters.convert(value, org.scenes.internal.target.Replay::fromKey,
                    org.scenes.internal.target.Replay.keys());
        }
    }

    /** {@code --compression gzip|zstd|none}: how scene files written into a directory are compressed. */
    public static final class Compression implements ITypeConverter<SceneCompression> {
        @Override
        public SceneCompression convert(String value) {
            return KeyConverters.convert(value, SceneCompression::fromKey, "gzip, zstd or none");
        }
    }

    /** {@code --commands rcl|infer|auto}: where a game's commands come from. */
    public static final class Commands implements ITypeConverter<GameLogs.Commands> {
        @Override
        public GameLogs.Commands convert(String value) {
            return KeyConverters.convert(value, GameLogs.Commands::named, "rcl, infer or auto");
        }
    }
}
