package org.scenes.simulator.teacher;

import java.util.Random;
import java.util.function.Consumer;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.simulator.Brain;

/**
 * A state-based Krislet: the same senses, but the choice depends on a state kept between sees,
 * so the same see can get different actions (what a stateless imitator cannot copy exactly).
 * <ul>
 * <li>search: ball not seen; turn towards the side it was last seen on;</li>
 * <li>chase: ball farther than 1 m; turn to it when more than 10 degrees off, else dash,
 *     gently (20 x distance) when close;</li>
 * <li>dribble: ball kickable, opponent goal seen farther than 30 m; kick 40 towards it;</li>
 * <li>shoot: ball kickable, goal within 30 m; kick 100 towards it;</li>
 * <li>look for the goal: ball kickable, goal not seen; turn 40.</li>
 * </ul>
 * Before kick-off it moves to a place of its half picked by its uniform number.
 */
final class StateBasedKrislet implements Brain {
    static final double KICKABLE = 1.0;
    static final double SHOOTING_RANGE = 30;
    static final double AIM_TOLERANCE = 10;

    enum State { SEARCH, CHASE, DRIBBLE, SHOOT, FIND_GOAL }

    private final Perception perception = new Perception();
    private final MessageParser parser = new MessageParser();
    private final Random random;
    private int unum;
    private boolean placed;
    private double lastBallDirection = 1;
    State state = State.SEARCH;

    StateBasedKrislet(Random random) {
        this.random = random;
    }

    @Override
    public void receive(String message, Consumer<String> send) {
        if (message.startsWith("(init") && parser.parse(message) instanceof InitReply reply) {
            unum = reply.uniformNumber();
        }
        boolean see = perception.read(message);
        if (!placed && message.startsWith("(player_type")) {
            placed = true;
            // Rows of three across the own half, deeper for higher numbers, a little jitter.
            int index = Math.max(0, unum - 1);
            double x = -8 - 12 * (index / 3) - random.nextDouble() * 2;
            double y = -20 + 20 * (index % 3) + random.nextDouble() * 2 - 1;
            send.accept(Commands.move(x, y));
            return;
        }
        if (see) {
            send.accept(decide());
        }
    }

    String decide() {
        VisualObject ball = perception.ball();
        if (ball == null) {
            state = State.SEARCH;
            return Commands.turn(lastBallDirection < 0 ? -40 : 40);
        }
        if (ball.direction() != 0) {
            lastBallDirection = ball.direction();
        }
        if (ball.distance() > KICKABLE) {
            state = State.CHASE;
            if (Math.abs(ball.direction()) > AIM_TOLERANCE) {
                return Commands.turn(ball.direction());
            }
            return Commands.dash(Math.min(100, (ball.distance() < 5 ? 20 : 10) * ball.distance()));
        }
        VisualObject goal = perception.opponentGoal();
        if (goal == null) {
            state = State.FIND_GOAL;
            return Commands.turn(40);
        }
        if (goal.distance() > SHOOTING_RANGE) {
            state = State.DRIBBLE;
            return Commands.kick(40, goal.direction());
        }
        state = State.SHOOT;
        return Commands.kick(100, goal.direction());
    }
}
