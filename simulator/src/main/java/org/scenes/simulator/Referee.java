package org.scenes.simulator;

import java.util.ArrayList;
import java.util.List;
import org.scenes.api.Side;

/**
 * Play modes and the clock: kick-off, goals, kick-ins, corner and goal kicks, half time and time
 * over. Each decision is announced as {@code (hear TIME referee MODE)}, delivered to every player
 * at the start of the next step.
 */
final class Referee {
    /**
     * Steps before a kick-off at the start and between the halves: the real server's auto mode
     * waits {@code kick_off_wait} (100) cycles once the teams are there (without it, an operator
     * starts the game).
     */
    static final int BEFORE_KICK_OFF_STEPS = 100;
    /** Steps the clock stands still after a goal before the kick-off (the server's after-goal wait, 50). */
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
    private final Physics physics;
    private final List<String> announcements = new ArrayList<>();
    /** The last play mode announced, as the referee words it ({@code goal_l_2}, {@code kick_in_r}). */
    private String modeWord = "before_kick_off";
    private int waited;
    private boolean secondHalf;

    Referee(World world, int cycles, Physics physics) {
        this.world = world;
        this.cycles = cycles;
        this.physics = physics;
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
                placePlayersInTheirHalves();
                if (++waited >= BEFORE_KICK_OFF_STEPS) {
                    kickOff(world.restartSide);
                }
            }
            case AFTER_GOAL -> {
                if (++waited >= PAUSE_STEPS) {
                    // The side that conceded kicks off.
                    kickOff(world.restartSide);
                }
            }
            case TIME_OVER -> {
            }
            default -> {
                if (world.mode == PlayMode.KICK_OFF) {
                    placePlayersInTheirHalves();
                }
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
            // As on the server: half_time, then before_kick_off with the right side to kick off.
            secondHalf = true;
            announce("half_time");
            world.mode = PlayMode.BEFORE_KICK_OFF;
            world.restartSide = Side.RIGHT;
            world.ball.place(0, 0);
            waited = 0;
            announce("before_kick_off");
            placePlayersInTheirHalves();
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
            // The ball stops where it is; players go on moving while the clock stands still.
            ball.place(ball.x, ball.y);
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
        world.ball.place(0, 0);
        world.mode = PlayMode.KICK_OFF;
        world.restartSide = side;
        waited = 0;
        placePlayersInTheirHalves();
        announce("kick_off_" + side.letter());
    }

    /**
     * Before and at a kick-off, as the server places players: one in the other half goes back to
     * its own, at a random spot of it before kick-off, and at a kick-off to the halfway line (its
     * own side of it by a player's size, same y); the side not kicking off leaves the centre circle
     * (to its edge, {@link #KEEP_AWAY} plus a player's size from the centre).
     */
    private void placePlayersInTheirHalves() {
        double size = world.params.playerSize();
        boolean kickOff = world.mode == PlayMode.KICK_OFF;
        for (Player player : world.players) {
            double sign = player.side == Side.LEFT ? -1 : 1;
            if (player.x * sign < 0) {
                if (kickOff) {
                    player.x = sign * size;
                } else {
                    player.x = sign * world.random.nextDouble() * ServerParams.PITCH_HALF_LENGTH;
                    player.y = (world.random.nextDouble() * 2 - 1) * ServerParams.PITCH_HALF_WIDTH;
                }
            }
            if (player.side != world.restartSide) {
                double radius = KEEP_AWAY + size;
                double distance = Math.hypot(player.x, player.y);
                if (distance < radius) {
                    double dx = distance == 0 ? sign : player.x / distance;
                    double dy = distance == 0 ? 0 : player.y / distance;
                    player.x = dx * radius;
                    player.y = dy * radius;
                }
            }
        }
    }

    /**
     * Until a restart is taken, the other side stays {@link #KEEP_AWAY} plus a player's size from
     * the ball: a player inside that circle is put on its edge, standing (then overlaps are
     * resolved), as the server clears players from the ball.
     */
    private void keepAway() {
        Ball ball = world.ball;
        double radius = KEEP_AWAY + world.params.playerSize();
        boolean moved = false;
        for (Player player : world.players) {
            if (player.side == world.restartSide) {
                continue;
            }
            double dx = player.x - ball.x;
            double dy = player.y - ball.y;
            double distance = Math.hypot(dx, dy);
            if (distance >= radius) {
                continue;
            }
            if (distance < 1e-9) {
                // On the ball: step back towards the own goal.
                dx = player.side == Side.LEFT ? -1 : 1;
                dy = 0;
                distance = 1;
            }
            // Put there standing, as the server places a cleared player.
            player.place(ball.x + dx / distance * radius, ball.y + dy / distance * radius);
            moved = true;
        }
        if (moved) {
            physics.collisions();
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
