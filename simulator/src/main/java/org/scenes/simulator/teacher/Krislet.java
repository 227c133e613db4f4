package org.scenes.simulator.teacher;

import java.util.Random;
import java.util.function.Consumer;
import org.scenes.api.Side;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.simulator.Brain;

/**
 * The classic Krislet rules, applied to the latest {@code see} (a ball seen behind, {@code (B)},
 * counts as the ball: the recorded Krislet turns to it and kicks it): no ball in sight, turn 40; ball far
 * and off centre, turn to it; ball far and straight ahead, dash with ten times its distance;
 * ball kickable and the opponent goal out of sight, turn 40; ball kickable and goal in sight,
 * kick 100 towards the goal. Before kick-off it moves to a random spot in its own half.
 *
 * <p>Timing as in the original client, whose think loop sleeps two simulator steps after each
 * command: it decides every second step (counted by {@code sense_body}, one per step) from the
 * latest see it has, so one command per 200 ms against a see every 150 ms: three sees in four get
 * an action, as in the recorded games (75 %), and never two commands in one cycle. The original
 * thinks 200 ms after its last command, at no fixed point of the cycle, so by then it nearly
 * always holds a see taken after that command took effect (92.5 % and 87.3 % of the decisions in
 * the recorded games {@code classic-game1} and {@code classic-game2}). A step's see comes after
 * its {@code sense_body}, so deciding on the {@code sense_body} alone would use a see from before
 * the last command one time in three, and turn twice for one offset; so when its latest see is
 * that old, this teacher decides on the step's see instead (or, should none come, at the next
 * {@code sense_body} on what it has).
 */
final class Krislet implements Brain {
    /** Krislet's kickable distance: the ball within a metre. */
    static final double KICKABLE = 1.0;
    /** Steps slept after each command. */
    static final int SLEEP_STEPS = 2;

    private final Perception perception = new Perception();
    private final Random random;
    private boolean placed;
    /** Steps (sense_body messages, one per step) since the last command. */
    private int stepsSinceCommand = SLEEP_STEPS - 1;
    /** Steps begun ({@code sense_body} messages received). */
    private int step;
    /** The step in which the last command went out, and the step in which the latest see came. */
    private int commandStep = -1;
    private int seeStep = -1;
    /** A decision is due and waits for a see taken after the last command. */
    private boolean waiting;

    Krislet(Random random) {
        this.random = random;
    }

    @Override
    public void receive(String message, Consumer<String> send) {
        perception.read(message);
        if (!placed && message.startsWith("(player_type")) {
            placed = true;
            send.accept(Commands.move(-random.nextDouble() * 52.5, 34 - random.nextDouble() * 68));
            return;
        }
        if (message.startsWith("(see")) {
            seeStep = step;
            if (waiting) {
                think(send);
            }
        } else if (message.startsWith("(sense_body")) {
            step++;
            if (waiting) {
                think(send); // no see came during the step: decide on what it has
            } else if (++stepsSinceCommand >= SLEEP_STEPS && perception.see != null) {
                if (seeStep > commandStep) {
                    think(send);
                } else {
                    waiting = true;
                }
            }
        }
    }

    private void think(Consumer<String> send) {
        waiting = false;
        stepsSinceCommand = 0;
        commandStep = step;
        send.accept(decide(perception));
    }

    static String decide(Perception perception) {
        return decide(perception.see, perception.side);
    }

    /** The rules on one see, for a player of {@code side}. */
    static String decide(See see, Side side) {
        VisualObject ball = Perception.find(see, "b");
        if (ball == null) {
            ball = Perception.find(see, "B");
        }
        if (ball == null) {
            return Commands.turn(40);
        }
        if (ball.distance() > KICKABLE) {
            if (ball.direction() != 0) {
                return Commands.turn(ball.direction());
            }
            return Commands.dash(10 * ball.distance());
        }
        VisualObject goal = Perception.opponentGoal(see, side);
        if (goal == null) {
            return Commands.turn(40);
        }
        return Commands.kick(100, goal.direction());
    }
}
