package org.scenes.evaluate;

import java.io.IOException;
import java.util.function.Consumer;
import java.util.function.IntConsumer;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;

/**
 * Where the games of an evaluation are played: the embedded simulator ({@link #embedded}), or a
 * live server reached through the UDP runtime ({@link LiveArena}, {@code scenes evaluate
 * --server HOST:PORT}), which connects the same brains and takes its frames from the server's
 * game log.
 */
@FunctionalInterface
public interface Arena {
    /**
     * Plays one game; {@code frames} gets the world after connecting and after every step,
     * {@code progress} the game clock.
     */
    GameResult play(GameSetup setup, IntConsumer progress, Consumer<GameFrame> frames) throws IOException;

    /** The embedded simulator, in process and synchronous. */
    static Arena embedded() {
        return (setup, progress, frames) -> new Simulator(setup).run(progress, frames);
    }
}
