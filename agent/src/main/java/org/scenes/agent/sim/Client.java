package org.scenes.agent.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import org.scenes.agent.Brain;

/**
 * An in-process client: delivers the engine's messages to a brain and hands its commands back
 * to the engine, logging both ways in the player's log.
 */
final class Client {
    private final Brain brain;
    private final PlayerLog log;
    private final Engine engine;
    private Seat seat;

    Client(Brain brain, PlayerLog log, Engine engine) {
        this.brain = brain;
        this.log = log;
        this.engine = engine;
    }

    void seat(Seat taken) {
        this.seat = taken;
    }

    /** Something the client sent on its own (its init). */
    void sentByClient(String command) {
        record(command);
    }

    void deliver(String message) {
        record(message);
        brain.receive(message, command -> {
            record(command);
            if (!engine.answerNow(seat, command)) {
                engine.received(seat, command);
            }
        });
    }

    PlayerLog log() {
        return log;
    }

    private void record(String line) {
        if (log == null) {
            return;
        }
        try {
            log.line(line);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
