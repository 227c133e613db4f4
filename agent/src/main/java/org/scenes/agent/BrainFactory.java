package org.scenes.agent;

import java.util.Random;

/** Makes one brain per player of a team. */
@FunctionalInterface
public interface BrainFactory {
    /**
     * @param team the team name the client sends in its init
     * @param random the brain's own random source (seeded by the game, so games repeat)
     */
    Brain create(String team, Random random);
}
