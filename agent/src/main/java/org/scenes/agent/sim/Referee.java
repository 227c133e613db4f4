package org.scenes.agent.sim;

import java.util.ArrayList;
import java.util.List;
import org.scenes.scene.Side;

/**
 * Play modes and the clock: kick-off, goals, kick-ins, corner and goal kicks, half time and time
 * over. Each decision is announced as {@code (hear TIME referee MODE)}, delivered to every player
 * at the start of the next step.
 */
final class Referee {
    /** Steps before the first kick-off; the real server waits for the operator or auto_mode. */
    static final int BEFORE_KICK_OFF_STEPS = 30;
    /** Steps the clock stands still after a goal and at half time (about 50 on the real server). */
    static final int PAUSE_STEPS = 50;
    /** How far the other side must stay from the ball at a restart ({@code offside_kick_margin}). */
    static final double KEEP_AWAY = 9.15;
    /** Cycles a kick-in, corner or goal kick may wait before the ball is dropped ({@code drop_ball_time}). */
    static final int DROP_BALL_TIME = 200;
    /** Corner kicks are taken this far inside the corner ({@code ckick_margin}). */
    static final double CORNER_MARGIN = 1;
    /** Goal kicks are taken from the corner of the goal area. */
    static final double GOAL_AREA_LENGTH = 5.5;
    static final double GOAL_AREA_HALF_WIDTH = 9.16;

    private final World world;
    private final int cycles;
    private final List<String> announcements = new ArrayList<>();
    /** The last play mode announced, as the referee words it ({@code goal_l_2}, {@code kick_in_r}). */
    private String modeWord = "before_kick_off";
    private int waited;
    private boolean secondHalf;

    Referee(World world, int cycles) {
        this.world = world;
        this.cycles = cycles;
    }

    /** Announcements made since the last call, as hear messages. */
    List<String> takeAnnouncements() {
        List<String> taken = List.copyOf(announcements);
        announcements.clear();
        return taken;
    }

    /** The current play mode in the referee's words, as a game log records it. */
    String playModeWord() {
        return modeWord;
    }

    /** Whether this player may kick now: at a restart only the side awarded it may. */
    boolean mayKick(Player player) {
        if (world.mode == PlayMode.PLAY_ON) {
            return true;
        }
        return world.mode.restart() && player.side == world.restartSide;
    }

    /** A kick touched the ball: a restart becomes play on. */
    void ballKicked(Player player) {
        world.lastTouch = player.side;
        if (world.mode.restart()) {
            world.mode = PlayMode.PLAY_ON;
            announce("play_on");
        }
    }

    /**
     * A goalie caught the ball: the referee says {@code goalie_catch_ball_X}, and the goalie's
     * side takes a free kick from where the ball is.
     */
    void caught(Player goalie) {
        world.lastTouch = goalie.side;
        announce("goalie_catch_ball_" + goalie.side.letter());
        world.mode = PlayMode.FREE_KICK;
        world.restartSide = goalie.side;
        waited = 0;
        announce("free_kick_" + goalie.side.letter());
    }

    /** Ends a step: judges the ball, then advances the clock or the pause. */
    void endStep() {
        switch (world.mode) {
            case BEFORE_KICK_OFF -> {
                if (++waited >= BEFORE_KICK_OFF_STEPS) {
                    kickOff(Side.LEFT);
                }
            }
            case AFTER_GOAL, HALF_TIME -> {
                if (++waited >= PAUSE_STEPS) {
                    // After a goal the side that conceded kicks off; the second half starts with the right.
                    kickOff(world.mode == PlayMode.HALF_TIME ? Side.RIGHT : world.restartSide);
                }
            }
            case TIME_OVER -> {
            }
            default -> {
                if (world.mode.restart()) {
                    keepAway();
                    if (world.mode != PlayMode.KICK_OFF && ++waited >= DROP_BALL_TIME) {
                        announce("drop_ball");
                        world.mode = PlayMode.PLAY_ON;
                        announce("play_on");
                    }
                }
                if (!judgeBall()) {
                    tick();
                }
            }
        }
    }

    private void tick() {
        world.time++;
        if (!secondHalf && world.time == cycles / 2 && cycles / 2 > 0) {
            secondHalf = true;
            world.mode = PlayMode.HALF_TIME;
            waited = 0;
            announce("half_time");
            resetPositions(Side.RIGHT);
        } else if (world.time >= cycles) {
            world.mode = PlayMode.TIME_OVER;
            announce("time_over");
        }
    }

    /** Goal or ball out of the pitch; returns whether play stopped for a goal. */
    private boolean judgeBall() {
        Ball ball = world.ball;
        double radius = world.params.ballSize();
        boolean overGoalLine = Math.abs(ball.x) > ServerParams.PITCH_HALF_LENGTH + radius;
        if (overGoalLine && Math.abs(ball.y) < world.params.goalWidth() / 2) {
            Side scorer = ball.x > 0 ? Side.LEFT : Side.RIGHT;
            int goals = scorer == Side.LEFT ? ++world.scoreLeft : ++world.scoreRight;
            announce("goal_" + scorer.letter() + "_" + goals);
            world.mode = PlayMode.AFTER_GOAL;
            world.restartSide = other(scorer);
            ball.place(Math.signum(ball.x) * (ServerParams.PITCH_HALF_LENGTH + 1), ball.y);
            waited = 0;
            return true;
        }
        if (overGoalLine) {
            Side defending = ball.x > 0 ? Side.RIGHT : Side.LEFT;
            double endX = Math.signum(ball.x);
            double sideY = ball.y >= 0 ? 1 : -1;
            if (world.lastTouch == defending) {
                restart(PlayMode.CORNER_KICK, other(defending), endX * (ServerParams.PITCH_HALF_LENGTH - CORNER_MARGIN),
                        sideY * (ServerParams.PITCH_HALF_WIDTH - CORNER_MARGIN));
            } else {
                restart(PlayMode.GOAL_KICK, defending, endX * (ServerParams.PITCH_HALF_LENGTH - GOAL_AREA_LENGTH),
                        sideY * GOAL_AREA_HALF_WIDTH);
            }
        } else if (Math.abs(ball.y) > ServerParams.PITCH_HALF_WIDTH + radius) {
            Side awarded = world.lastTouch == null ? Side.LEFT : other(world.lastTouch);
            restart(PlayMode.KICK_IN, awarded,
                    Physics.clamp(ball.x, -ServerParams.PITCH_HALF_LENGTH, ServerParams.PITCH_HALF_LENGTH),
                    Math.signum(ball.y) * ServerParams.PITCH_HALF_WIDTH);
        }
        return false;
    }

    private void restart(PlayMode mode, Side side, double x, double y) {
        world.ball.place(x, y);
        world.mode = mode;
        world.restartSide = side;
        waited = 0;
        announce(mode.word + "_" + side.letter());
    }

    private void kickOff(Side side) {
        resetPositions(side);
        world.mode = PlayMode.KICK_OFF;
        world.restartSide = side;
        announce("kick_off_" + side.letter());
    }

    /**
     * Ball to the centre; players in the other half go back to their own, and the side not
     * kicking off leaves the centre circle, as the server places players before a kick-off.
     */
    private void resetPositions(Side kicking) {
        world.ball.place(0, 0);
        for (Player player : world.players) {
            double sign = player.side == Side.LEFT ? -1 : 1;
            if (player.x * sign < 0) {
                player.x = -player.x;
            }
            player.vx = 0;
            player.vy = 0;
        }
        world.restartSide = kicking;
        keepAway();
    }

    /** Until the restart is taken, the other side stays {@link #KEEP_AWAY} from the ball. */
    private void keepAway() {
        Ball ball = world.ball;
        for (Player player : world.players) {
            if (player.side == world.restartSide) {
                continue;
            }
            double dx = player.x - ball.x;
            double dy = player.y - ball.y;
            double distance = Math.hypot(dx, dy);
            if (distance >= KEEP_AWAY) {
                continue;
            }
            if (distance < 1e-9) {
                // On the ball: step back towards the own goal.
                dx = player.side == Side.LEFT ? -1 : 1;
                dy = 0;
                distance = 1;
            }
            player.x = ball.x + dx / distance * KEEP_AWAY;
            player.y = ball.y + dy / distance * KEEP_AWAY;
        }
    }

    private static Side other(Side side) {
        return side == Side.LEFT ? Side.RIGHT : Side.LEFT;
    }

    private void announce(String mode) {
        modeWord = mode;
        announcements.add("(hear " + world.time + " referee " + mode + ")");
    }
}
