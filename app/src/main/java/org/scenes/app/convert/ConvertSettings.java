package org.scenes.app.convert;

import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.Predicate;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.MalformedLine;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.vision.Fading;

/**
 * How logs become scenes, for player logs and game logs alike: the options of {@code scenes
 * convert} as one value, so the single-log, single-game and archive conversions build their
 * converters in one place.
 *
 * @param grid the scene grid
 * @param pairing how sees and actions pair
 * @param strict stop at the first malformed line of a player log
 * @param world scenes carry the player's world model
 * @param keepUnanswered a see left unanswered becomes a scene without action
 * @param fading game logs: how a seen player's team and number fade with distance
 * @param selected game logs: the players converted
 * @param commandsFirst game logs: a player's commands came before its see within a step
 * @param seePhase game logs: where asynchronous see clocks start
 * @param threads game logs: threads rebuilding a game's players
 * @param compression how scene files written into a directory are compressed
 */
public record ConvertSettings(Grid grid, Pairing pairing, boolean strict, boolean world, boolean keepUnanswered,
                              Fading fading, Predicate<Observer> selected, boolean commandsFirst,
                              GameLogConverter.SeePhase seePhase, int threads,
                              SceneCompression compression) {
    public ConvertSettings {
        Objects.requireNonNull(grid, "grid");
        Objects.requireNonNull(pairing, "pairing");
        Objects.requireNonNull(fading, "fading");
        Objects.requireNonNull(selected, "selected");
        Objects.requireNonNull(seePhase, "seePhase");
        Objects.requireNonNull(compression, "compression");
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be 1 or more, not " + threads);
        }
    }

    /** The converter of player logs, reporting each malformed line to {@code warnings}. */
    SceneConverter playerLogConverter(Consumer<MalformedLine> warnings) {
        return SceneConverter.with(grid).pairing(pairing).strict(strict).warnings(warnings).world(world)
                .keepUnanswered(keepUnanswered).build();
    }

    /** The converter of a game's server logs. */
    GameLogConverter gameLogConverter() {
        return new GameLogConverter(grid, pairing, fading, selected, threads).commandsBeforeSee(commandsFirst)
                .seePhase(seePhase).world(world).keepUnanswered(keepUnanswered);
    }
}
