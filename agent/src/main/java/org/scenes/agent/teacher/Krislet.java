package org.scenes.agent.teacher;

import java.util.Random;
import java.util.function.Consumer;
import org.scenes.agent.Brain;
import org.scenes.protocol.See;
import org.scenes.protocol.VisualObject;
import org.scenes.scene.Side;

/**
 * The classic Krislet rules, applied to the latest {@code see}: no ball in sight, turn 40; ball far
 * and off centre, turn to it; ball far and straight ahead, dash with ten times its distance;
 * ball kickable and the opponent goal out of sight, turn 40; ball kickable and goal in sight,
 * kick 100 towards the goal. Before kick-off it moves to a random spot in its own half.
 *
 * <p>Timing as in the original client, whose think loop sleeps two simulator steps after each
 * command: it decides every second step (counted by {@code sense_body}, one per step) from the
 * latest see it has, so one command per 200 ms against a see every 150 ms: three sees in four get
 * an action, as in the recorded games (75 %), and never two commands in one cycle.
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
        if (message.startsWith("(sense_body") && ++stepsSinceCommand >= SLEEP_STEPS && perception.see != null) {
            stepsSinceCommand = 0;
            send.accept(decide(perception));
        }
    }

    static String decide(Perception perception) {
        return decide(perception.see, perception.side);
    }

    /** The rules on one see, for a player of {@code side}. */
    static String decide(See see, Side side) {
        VisualObject ball = Perception.find(see, "b");
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
