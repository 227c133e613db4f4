package org.scenes.simulator;

import java.util.Map;
import java.util.function.Consumer;

/**
 * A player client: it reads the server's messages as protocol text and answers with command
 * text, exactly what it would exchange with a real server over UDP. The embedded simulator calls
 * it synchronously, one message at a time, in arrival order.
 */
public interface Brain {
    /**
     * Handles one server message (the init reply, parameters, {@code sense_body}, {@code see},
     * {@code hear}, errors) and sends zero or more commands through {@code send}.
     */
    void receive(String message, Consumer<String> send);

    /**
     * Whether the runtime sends this brain's kick-off {@code move} again at the start of the two
     * cycles after a goal or half time (the default, see {@code agent.net.LivePlayer}). An imitator
     * whose teacher never moved after a goal answers false: it does not send moves its teacher
     * never sent.
     */
    default boolean repeatsKickOffMove() {
        return true;
    }

    /** What the brain counts of itself, by name, for the runtime's report (an imitator: decisions, guards). */
    default Map<String, Long> counters() {
        return Map.of();
    }
}
