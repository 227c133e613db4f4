package org.scenes.evaluate;

import java.util.Map;
import java.util.Random;
import java.util.function.Consumer;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/**
 * Gives a brain the think loop of the Krislet client: it decides at most once per {@code steps}
 * steps (counted by {@code sense_body}, one per step), where on its own it answers every see (two
 * steps of three). A fraction is kept over: 1.96 decides every second step and now and then after
 * one, as the client does on a real-time server whose steps last a little longer than its 200 ms
 * sleep's half (51 % of the steps with a body command, against 50 % for 2). As the teacher does, it decides on a see taken after its last decision: when the
 * latest see is older, it waits for the step's see (or, should none come, decides at the next
 * {@code sense_body} on what it has). The policy (which action for which scene) is the brain's;
 * only the tempo is the teacher's.
 */
public final class PacedBrain implements Brain {
    private final Brain inner;
    private final double steps;
    private String latestSee;
    /** Steps counted towards the next decision, the fraction beyond the last one's kept. */
    private double stepsSinceDecision;
    /** Steps begun, the step of the last decision and the step in which the latest see came. */
    private int step;
    private int decisionStep = -1;
    private int seeStep = -1;
    /** A decision is due and waits for a see taken after the last one. */
    private boolean waiting;

    private PacedBrain(Brain inner, double steps) {
        this.inner = inner;
        this.steps = steps;
        this.stepsSinceDecision = steps - 1;
    }

    /** The brains of {@code factory} paced to one decision per {@code steps} steps; 0 leaves them as they are. */
    public static BrainFactory pace(BrainFactory factory, double steps) {
        if (!valid(steps)) {
            throw new IllegalArgumentException("think steps must be 0, or 1 or more, not " + text(steps));
        }
        if (steps == 0) {
            return factory;
        }
        return new BrainFactory() {
            @Override
            public Brain create(String team, Random random) {
                return new PacedBrain(factory.create(team, random), steps);
            }

            @Override
            public boolean goalie(int unum) {
                return factory.goalie(unum);
            }
        };
    }

    /** One brain paced to one decision per {@code steps} steps; 0 leaves it as it is. */
    static Brain pace(Brain brain, double steps) {
        if (!valid(steps)) {
            throw new IllegalArgumentException("think steps must be 0, or 1 or more, not " + text(steps));
        }
        return steps == 0 ? brain : new PacedBrain(brain, steps);
    }

    /** Whether {@code steps} paces a brain: 0 (not paced), or a finite 1 or more. */
    public static boolean valid(double steps) {
        return steps == 0 || steps >= 1 && !Double.isInfinite(steps);
    }

    /** Steps as a person writes them: 2, 1.96. */
    public static String text(double steps) {
        return steps == Math.rint(steps) && Math.abs(steps) < 1e15 ? Long.toString((long) steps) : Double.toString(steps);
    }

    @Override
    public boolean repeatsKickOffMove() {
        return inner.repeatsKickOffMove();
    }

    @Override
    public Map<String, Long> counters() {
        return inner.counters();
    }

    @Override
    public void receive(String message, Consumer<String> send) {
        if (message.startsWith("(see ")) {
            latestSee = message;
            seeStep = step;
            if (waiting) {
                decide(send);
            }
            return;
        }
        inner.receive(message, send);
        if (message.startsWith("(sense_body")) {
            step++;
            if (waiting) {
                decide(send); // no see came during the step: decide on what it has
            } else if (++stepsSinceDecision >= steps && latestSee != null) {
                if (seeStep > decisionStep) {
                    decide(send);
                } else {
                    waiting = true;
                }
            }
        }
    }

    private void decide(Consumer<String> send) {
        waiting = false;
        // only the fraction of a step is carried over (none for whole steps): a wait for a see is not
        stepsSinceDecision = Math.max(0, Math.min(stepsSinceDecision - steps, steps - Math.floor(steps)));
        decisionStep = step;
        inner.receive(latestSee, send);
    }
}
