package org.scenes.simulator;

import java.nio.file.Path;
import java.util.Objects;

/**
 * What to simulate.
 *
 * @param left the team on the left (kicks off first)
 * @param right the team on the right
 * @param cycles the game length in cycles (half time at half of it)
 * @param seed the seed of all randomness: the same setup gives the same game, byte for byte
 * @param logDirectory where each player's log goes ({@code TEAM_UNUM.lsf.gz}); null for no logs
 */
public record GameSetup(Team left, Team right, int cycles, long seed, Path logDirectory) {
    /** The most players a side may have, as on the real server. */
    public static final int MAX_PLAYERS = 11;

    /** One side: its name, how many players, and the brain that plays each of them. */
    public record Team(String name, int players, BrainFactory brains) {
        public Team {
            Objects.requireNonNull(brains, "brains");
            if (name == null || !name.matches("[A-Za-z0-9_-]{1,15}")) {
                throw new IllegalArgumentException("team name must be 1 to 15 letters, digits, '-' or '_': " + name);
            }
            if (players < 1 || players > MAX_PLAYERS) {
                throw new IllegalArgumentException("a team has 1 to " + MAX_PLAYERS + " players, not " + players);
            }
        }
    }

    public GameSetup {
        Objects.requireNonNull(left, "left");
        Objects.requireNonNull(right, "right");
        if (left.name().equals(right.name())) {
            throw new IllegalArgumentException("the two teams need different names, both are " + left.name());
        }
        if (cycles < 1) {
            throw new IllegalArgumentException("cycles must be at least 1, not " + cycles);
        }
    }
}
