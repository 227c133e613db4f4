package org.scenes.internal.target;

import static org.scenes.internal.vision.Landmarks.PITCH_HALF_LENGTH;
import static org.scenes.internal.vision.Landmarks.PITCH_HALF_WIDTH;
import static org.scenes.internal.world.ServerDefaults.BALL_DECAY;

import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Relation;
import org.scenes.api.World;

/**
 * Who reaches a kicked ball first, as the kicker's world model tells: the ball follows the
 * server's kick and decay models, each player it knows of runs at the default player's top
 * speed after one turn (as in {@link BallRace}). A recorded kick carried out from another place
 * sends the ball where the recorded player's teammates stood, not necessarily where the kicker's
 * stand; this tells the kicks that score or keep the ball from those that lose it to an opponent
 * or over the line.
 */
public final class KickCourse {
    /** Cycles of the ball's course followed: a kick at full speed has rolled about 40 m by then. */
    static final int HORIZON = 30;
    /** Players remembered longer ago than this are left out: where they stand now is a guess. */
    static final int PLAYER_AGE = 10;
    /** The ball's top speed (rcssserver's {@code ball_speed_max}), metres a cycle. */
    static final double BALL_SPEED_MAX = 3;
    /** Half the goal's width (rcssserver's {@code goal_width} 14.02). */
    static final double GOAL_HALF_WIDTH = 7.01;

    private KickCourse() {
    }

    /** What becomes of a kicked ball, as the kicker's world model tells. */
    public enum Outcome {
        /** it goes into the opponent goal before any opponent reaches it */
        SCORES,
        /** the kicker or a teammate not offside reaches it first, and it stays on the pitch */
        KEEPS,
        /** an opponent reaches it first, or it leaves the pitch other than into the goal */
        LOST,
        /** not a kick, or the world model cannot tell (the kicker or the ball not located, the ball out of reach) */
        UNKNOWN
    }

    /**
     * What becomes of the ball of {@code kick} sent by the player of {@code own}: followed for
     * {@link #HORIZON} cycles, it scores when it crosses the goal line between the posts before any
     * opponent {@code own} knows of can reach it; it is lost when such an opponent reaches it no
     * later than the kicker or a teammate not offside ({@link #offsideLine}), or when it leaves the
     * pitch elsewhere, whoever reached it first (the imitators' kickers and receivers rarely stop
     * a ball); else it is kept.
     */
    public static Outcome outcome(Action kick, World own) {
        if (kick == null || kick.type() != ActionType.KICK || own == null || !own.located() || !own.ballKnown()) {
            return Outcome.UNKNOWN;
        }
        double rate = Targets.kickRate(own);
        if (!(rate > 0)) {
            return Outcome.UNKNOWN;
        }
        double[] kicked = Targets.kickedBall(kick, own, rate);
        double vx = kicked[0];
        double vy = kicked[1];
        double speed = Math.hypot(vx, vy);
        if (speed > BALL_SPEED_MAX) {
            vx *= BALL_SPEED_MAX / speed;
            vy *= BALL_SPEED_MAX / speed;
        }
        double bx = own.ballX();
        double by = own.ballY();
        double line = offsideLine(own);
        double offside = line == Double.NEGATIVE_INFINITY ? Double.POSITIVE_INFINITY : Math.max(Math.max(line, bx), 0);
        int teamFirst = Integer.MAX_VALUE;
        int opponentFirst = Integer.MAX_VALUE;
        for (int t = 1; t <= HORIZON; t++) {
            bx += vx;
            by += vy;
            vx *= BALL_DECAY;
            vy *= BALL_DECAY;
            if (Math.abs(bx) > PITCH_HALF_LENGTH || Math.abs(by) > PITCH_HALF_WIDTH) {
                return bx > PITCH_HALF_LENGTH && Math.abs(by) < GOAL_HALF_WIDTH && opponentFirst == Integer.MAX_VALUE
                        ? Outcome.SCORES : Outcome.LOST;
            }
            double reach = Targets.reach(t);
            if (teamFirst == Integer.MAX_VALUE && Math.hypot(bx - own.x(), by - own.y()) <= reach) {
                teamFirst = t;
            }
            for (World.Player player : own.players()) {
                if (player.age() > PLAYER_AGE || Double.isNaN(player.x())
                        || Math.hypot(bx - player.x(), by - player.y()) > reach) {
                    continue;
                }
                if (player.relation() == Relation.OPPONENT) {
                    opponentFirst = Math.min(opponentFirst, t);
                } else if (player.relation() == Relation.TEAMMATE && player.x() <= offside) {
                    teamFirst = Math.min(teamFirst, t);
                }
            }
            if (opponentFirst <= teamFirst && opponentFirst != Integer.MAX_VALUE) {
                return Outcome.LOST;
            }
        }
        return Outcome.KEEPS;
    }

    /**
     * The x of the second-last opponent the player knows of (its own frame attacks +x), or -infinity
     * when it knows fewer than two: a teammate beyond it and beyond the ball, in the opponents'
     * half, is offside when the ball is played to it.
     */
    static double offsideLine(World own) {
        double last = Double.NEGATIVE_INFINITY;
        double secondLast = Double.NEGATIVE_INFINITY;
        for (World.Player player : own.players()) {
            if (player.relation() != Relation.OPPONENT || player.age() > PLAYER_AGE || Double.isNaN(player.x())) {
                continue;
            }
            if (player.x() > last) {
                secondLast = last;
                last = player.x();
            } else if (player.x() > secondLast) {
                secondLast = player.x();
            }
        }
        return secondLast;
    }
}
