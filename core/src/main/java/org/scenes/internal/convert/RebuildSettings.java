package org.scenes.internal.convert;

import java.util.function.Predicate;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.internal.vision.Fading;

/** How {@link GameLogConverter} was set up, handed to the parts of one conversion. */
record RebuildSettings(Grid grid, Pairing pairing, Fading fading, Predicate<Observer> selected, int threads,
                       boolean commandsBeforeSee, GameLogConverter.SeePhase seePhase, boolean keepUnanswered,
                       boolean world) {

    /** A fresh converter of rebuilt messages into scenes, one per worker. */
    SceneConverter sceneConverter() {
        return SceneConverter.with(grid).pairing(pairing).world(world).keepUnanswered(keepUnanswered).build();
    }
}
