package org.scenes.evaluate;

import java.util.List;
import org.scenes.agent.sim.GameResult;
import org.scenes.gamelog.GameFrame;

/**
 * One game of an evaluation: who played on the left (the side evaluated), the seed, the result,
 * the world after every step and each left player's trace.
 */
public record PlayedGame(Role role, long seed, GameResult result, List<GameFrame> frames, List<PlayerTrace> traces) {
    /** Who drove the left team. */
    public enum Role {
        TEACHER("teacher"), IMITATOR("imitator");

        private final String label;

        Role(String label) {
            this.label = label;
        }

        public String label() {
            return label;
        }
    }

    public PlayedGame {
        frames = List.copyOf(frames);
        traces = List.copyOf(traces);
    }
}
