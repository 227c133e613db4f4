package org.scenes.simulator;

import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * An in-process client: delivers the engine's messages to a brain and hands its commands back
 * to the engine, logging both ways in the player's log. Like the live runtime
 * ({@code agent.net.LivePlayer}), it remembers the brain's {@code move} and sends it again at
 * the start of the two cycles after a goal or half time, so that a game played in process and
 * the same game over UDP stay identical to the end.
 */
final class Client {
    private final Brain brain;
    private final PlayerLog log;
    private final Engine engine;
    private Seat seat;
    /** The brain's last move, and how many cycle starts still get it again. */
    private String kickOffMove;
    private int movesOwed;

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
        if (message.startsWith("(sense_body") && movesOwed > 0 && kickOffMove != null && brain.repeatsKickOffMove()) {
            movesOwed--;
            send(kickOffMove);
        } else if (message.startsWith("(hear ") && (message.contains(" referee goal_")
                || message.endsWith(" referee half_time)"))) {
            movesOwed = 2;
        }
        brain.receive(message, command -> {
            if (command.startsWith("(move")) {
                kickOffMove = command;
            }
            send(command);
        });
    }

    private void send(String command) {
        record(command);
        if (!engine.answerNow(seat, command)) {
            engine.received(seat, command);
        }
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
