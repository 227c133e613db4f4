package org.scenes.internal.target;

import org.scenes.api.Relation;
import org.scenes.api.World;

/**
 * Where a player stands in the race to its ball, as its world model tells: how many cycles it
 * needs to reach the ball's course ({@link Targets#reachCycles}) and whether a teammate or an
 * opponent it knows of needs fewer. In HELIOS base's games against itself its players (goalie
 * aside) who would reach the ball first of everyone within nine cycles did so within 30 cycles in
 * 64 % to 100 % of the frames; those an opponent would beat, in 3 % to 16 %, however near
 * (the game log's true positions, game 2). Distance alone does not tell the two apart.
 *
 * @param cycles cycles the player needs, {@link Targets#INTERCEPT_HORIZON} when it cannot within them
 * @param standing who, if anyone, it knows to be faster
 */
record BallRace(int cycles, Standing standing) {
    /** Who beats the player to the ball. */
    enum Standing {
        /** a teammate it knows of is faster */
        TEAMMATE_FIRST,
        /** no teammate, but an opponent it knows of is faster */
        OPPONENT_FIRST,
        /** nobody it knows of is faster */
        FIRST
    }

    /** The race of the player of {@code world}; null when its world model knows no position or no ball. */
    static BallRace of(World world) {
        return of(world, 1);
    }

    /**
     * The same, where an opponent beats the player only when it needs {@code opponentLead} cycles
     * fewer or more (1: any opponent faster; a teammate faster always beats it).
     */
    static BallRace of(World world, int opponentLead) {
        if (world == null || !world.located() || !world.ballKnown()) {
            return null;
        }
        int own = Targets.reachCycles(world.x(), world.y(), world, Targets.INTERCEPT_HORIZON);
        Standing standing = Standing.FIRST;
        for (World.Player player : world.players()) {
            boolean teammate = player.relation() == Relation.TEAMMATE;
            if (!teammate && (player.relation() != Relation.OPPONENT || standing == Standing.OPPONENT_FIRST)) {
                continue;
            }
            // only a player enough faster than this one matters: its search stops there
            int faster = teammate ? own : own - opponentLead + 1;
            if (faster > 0 && Targets.reachCycles(player.x(), player.y(), world, faster) < faster) {
                if (teammate) {
                    return new BallRace(own, Standing.TEAMMATE_FIRST);
                }
                standing = Standing.OPPONENT_FIRST;
            }
        }
        return new BallRace(own, standing);
    }
}
