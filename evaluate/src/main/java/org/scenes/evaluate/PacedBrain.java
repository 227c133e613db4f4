package org.scenes.evaluate;

import java.util.function.Consumer;
import org.scenes.agent.Brain;
import org.scenes.agent.BrainFactory;

/**
 * Gives a brain the think loop of the Krislet client: it is handed the latest {@code see} only
 * every {@code steps}-th {@code sense_body} (one per step) and so answers at most once per
 * {@code steps} steps, where on its own it answers every see (two steps of three). The policy
 * (which action for which scene) is the brain's; only the tempo is the teacher's.
 */
public final class PacedBrain implements Brain {
    private final Brain inner;
    private final int steps;
    private String latestSee;
    private int stepsSinceDecision;

    private PacedBrain(Brain inner, int steps) {
        this.inner = inner;
        this.steps = steps;
        this.stepsSinceDecision = steps - 1;
    }

    /** The brains of {@code factory} paced to one decision per {@code steps} steps; 0 leaves them as they are. */
    public static BrainFactory pace(BrainFactory factory, int steps) {
        if (steps < 0) {
            throw new IllegalArgumentException("think steps must be 0 or more, not " + steps);
        }
        return steps == 0 ? factory : (team, random) -> new PacedBrain(factory.create(team, random), steps);
    }

    @Override
    public void receive(String message, Consumer<String> send) {
        if (message.startsWith("(see ")) {
            latestSee = message;
            return;
        }
        inner.receive(message, send);
        if (message.startsWith("(sense_body") && ++stepsSinceDecision >= steps && latestSee != null) {
            stepsSinceDecision = 0;
            inner.receive(latestSee, send);
        }
    }
}
