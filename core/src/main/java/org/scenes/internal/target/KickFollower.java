package org.scenes.internal.target;

import java.util.List;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.World;

/**
 * A player that kicked the ball in play on goes after it while it can contest it ({@link #contests}).
 * HELIOS base's slow kicks (under 1.2 m a cycle, no opponent within 3 m) were followed by
 * the same player's next kick in 95 to 98 % (its games 2, 5 and 6, the game logs); its imitators'
 * in 61 to 71 %, and in 14 to 22 % an opponent's came next: after the kick their next scene's
 * target was rarely the ball, and the kicker walked away from its own dribble. Not thread-safe:
 * one per player.
 */
public final class KickFollower {
    /** Cycles after its kick that a player follows the ball: HELIOS base's own next kick came 3.6 cycles later on average. */
    static final int FOLLOW = 10;
    /** Cycles an opponent must be sooner at the ball to end the follow (HELIOS base's players intercept unless 3 behind). */
    static final int OPPONENT_LEAD = 3;
    /** the cycle of the player's latest kick in play on; far in the past before its first */
    private long kickedAt = Integer.MIN_VALUE;
    private long follows;

    /**
     * {@code actions} (body action first), or a run to where the player can reach its ball in place
     * of the body action (the neck's stays) when the player kicked in play on within the last
     * {@link #FOLLOW} cycles, the ball is out of its reach, no kick is chosen, and it {@link #contests}
     * the ball.
     *
     * @param power the dash power to run with
     */
    public List<Action> follow(List<Action> actions, World own, int cycle, double power) {
        if (cycle - kickedAt > FOLLOW || cycle <= kickedAt || !Targets.mayRun(actions, own) || !contests(own)) {
            return actions;
        }
        follows++;
        return Targets.withBody(Targets.runTo(Targets.intercept(own), own, power), actions);
    }

    /**
     * Whether the player goes for the ball as HELIOS base's players decide to intercept: it can
     * reach the ball's course within {@link #FOLLOW} cycles, no teammate it knows of sooner, and no
     * opponent it knows of {@link #OPPONENT_LEAD} cycles or more sooner (a near race is contested).
     */
    static boolean contests(World own) {
        BallRace race = BallRace.of(own, OPPONENT_LEAD);
        return race != null && race.standing() == BallRace.Standing.FIRST && race.cycles() <= FOLLOW;
    }

    /** Notes the actions sent in {@code cycle}: a kick in play on starts a follow. */
    public void sent(List<Action> actions, World own, int cycle) {
        if (own != null && "play_on".equals(own.playMode())
                && actions.stream().anyMatch(action -> action.type() == ActionType.KICK)) {
            kickedAt = cycle;
        }
    }

    /** Decisions that ran after the player's own kick. */
    public long follows() {
        return follows;
    }
}
