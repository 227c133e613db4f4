package org.scenes.agent.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import org.scenes.agent.Brain;

/** The simulator's end of one player's connection: delivers text to the brain, logs both ways. */
final class Client {
    final Player player;
    private final Brain brain;
    private final PlayerLog log;
    /** Commands sent since the server last executed this client's commands. */
    final List<String> sent = new ArrayList<>();

    Client(Player player, Brain brain, PlayerLog log) {
        this.player = player;
        this.brain = brain;
        this.log = log;
    }

    /** Something the client sent on its own (its init). */
    void sentByClient(String command) {
        record(command);
    }

    void deliver(String message) {
        record(message);
        brain.receive(message, command -> {
            record(command);
            sent.add(command);
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
