package org.scenes.simulator;

import java.util.Random;

/** Makes one brain per player of a team. */
@FunctionalInterface
public interface BrainFactory {
    /**
     * @param team the team name the client sends in its init
     * @param random the brain's own random source (seeded by the game, so games repeat)
     */
    Brain create(String team, Random random);

    /**
     * Whether the player that gets this uniform number should init as its team's goalie (players
     * connect in order, so the Nth gets number N): an imitator of a recorded goalie does.
     *
     * @param unum the uniform number, from 1
     */
    default boolean goalie(int unum) {
        return false;
    }
}
