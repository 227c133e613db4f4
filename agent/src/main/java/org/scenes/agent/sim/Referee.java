package org.scenes.agent.sim;

import java.util.ArrayList;
import java.util.List;
import org.scenes.scene.Side;

/**
 * Play modes and the clock: kick-off, goals, ball out of the pitch, half time and time over. Each
 * decision is announced as {@code (hear TIME referee MODE)}, delivered to every player at the
 * start of the next step.
 */
final class Referee {
    /** Steps before the first kick-off; the real server waits for the operator or auto_mode. */
    static final int BEFORE_KICK_OFF_STEPS = 30;
    /** Steps the clock stands still after a goal and at half time (about 50 on the real server). */
    static final int PAUSE_STEPS = 50;
    /** Radius of the centre circle the defending team must stay outside of at kick-off. */
    static final double CENTRE_CIRCLE = 9.15;

    private final World world;
    private final int cycles;
    private final List<String> announcements = new ArrayList<>();
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

    /** Whether this player may kick now: at kick-off only the kicking side may. */
    boolean mayKick(Player player) {
        return switch (world.mode) {
            case PLAY_ON -> true;
            case KICK_OFF -> player.side == world.kickOffSide;
            default -> false;
        };
    }

    /** A kick touched the ball: a kick-off becomes play on. */
    void ballKicked() {
        if (world.mode == PlayMode.KICK_OFF) {
            world.mode = PlayMode.PLAY_ON;
            announce("play_on");
        }
    }

    /** Ends a step: judges the ball, then advances the clock or the pause. */
    void endStep() {
        switch (world.mode) {
            case BEFORE_KICK_OFF -> {
                if (++waited >= BEFORE_KICK_OFF_STEPS) {
                    kickOff(Side.LEFT);
                }
            }
            case KICK_OFF, PLAY_ON -> {
                if (world.mode == PlayMode.KICK_OFF) {
                    keepDefendersAway();
                }
                if (!judgeBall()) {
                    tick();
                }
            }
            case AFTER_GOAL, HALF_TIME -> {
                if (++waited >= PAUSE_STEPS) {
                    // After a goal the side that conceded kicks off; the second half starts with the right.
                    kickOff(world.mode == PlayMode.HALF_TIME ? Side.RIGHT : world.kickOffSide);
                }
            }
            case TIME_OVER -> {
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

    /** Goal or ball out; returns whether play stopped for a goal. */
    private boolean judgeBall() {
        Ball ball = world.ball;
        double halfGoal = world.params.goalWidth() / 2;
        if (Math.abs(ball.x) > ServerParams.PITCH_HALF_LENGTH && Math.abs(ball.y) < halfGoal) {
            Side scorer = ball.x > 0 ? Side.LEFT : Side.RIGHT;
            int goals = scorer == Side.LEFT ? ++world.scoreLeft : ++world.scoreRight;
            announce("goal_" + scorer.letter() + "_" + goals);
            world.mode = PlayMode.AFTER_GOAL;
            world.kickOffSide = scorer == Side.LEFT ? Side.RIGHT : Side.LEFT;
            ball.place(Math.signum(ball.x) * (ServerParams.PITCH_HALF_LENGTH + 1), ball.y);
            waited = 0;
            return true;
        }
        if (Math.abs(ball.x) > ServerParams.PITCH_HALF_LENGTH || Math.abs(ball.y) > ServerParams.PITCH_HALF_WIDTH) {
            // Simplified restart: the ball is dropped just inside where it left and play goes on.
            ball.place(Physics.clamp(ball.x, -ServerParams.PITCH_HALF_LENGTH + 1, ServerParams.PITCH_HALF_LENGTH - 1),
                    Physics.clamp(ball.y, -ServerParams.PITCH_HALF_WIDTH + 1, ServerParams.PITCH_HALF_WIDTH - 1));
            announce("drop_ball");
            world.mode = PlayMode.PLAY_ON;
            announce("play_on");
        }
        return false;
    }

    private void kickOff(Side side) {
        resetPositions(side);
        world.kickOffSide = side;
        world.mode = PlayMode.KICK_OFF;
        announce("kick_off_" + side.letter());
    }

    /**
     * Ball to the centre; players in the other half go back to their own, and the defending side
     * leaves the centre circle, as the server places players before a kick-off.
     */
    private void resetPositions(Side kicking) {
        world.ball.place(0, 0);
        for (Player player : world.players) {
            double sign = player.side == Side.LEFT ? -1 : 1;
            if (player.x * sign < 0) {
                player.x = -player.x;
            }
            if (player.side != kicking) {
                pushOutOfCentreCircle(player);
            }
            player.vx = 0;
            player.vy = 0;
        }
    }

    /** Until the kick-off is taken, the defending side stays outside the centre circle. */
    private void keepDefendersAway() {
        for (Player player : world.players) {
            if (player.side != world.kickOffSide) {
                pushOutOfCentreCircle(player);
            }
        }
    }

    private static void pushOutOfCentreCircle(Player player) {
        double fromCentre = Math.hypot(player.x, player.y);
        if (fromCentre >= CENTRE_CIRCLE) {
            return;
        }
        if (fromCentre < 1e-9) {
            player.x = (player.side == Side.LEFT ? -1 : 1) * CENTRE_CIRCLE;
        } else {
            player.x *= CENTRE_CIRCLE / fromCentre;
            player.y *= CENTRE_CIRCLE / fromCentre;
        }
    }

    private void announce(String mode) {
        announcements.add("(hear " + world.time + " referee " + mode + ")");
    }
}
