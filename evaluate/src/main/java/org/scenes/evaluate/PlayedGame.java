package org.scenes.evaluate;

import java.util.List;
import org.scenes.agent.sim.GameResult;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;

/**
 * One game seen from one side: who played there, which side it was, the seed, the result, the
 * world after every step and each of that side's players' traces.
 */
public record PlayedGame(Role role, Side side, long seed, GameResult result, List<GameFrame> frames,
                         List<PlayerTrace> traces) {
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

    /** Goals the side scored. */
    public int goalsFor() {
        return side == Side.LEFT ? result.scoreLeft() : result.scoreRight();
    }

    public int goalsAgainst() {
        return side == Side.LEFT ? result.scoreRight() : result.scoreLeft();
    }

    /** Kicks of the side that touched the ball. */
    public int kicks() {
        return side == Side.LEFT ? result.kicksLeft() : result.kicksRight();
    }

    public PlayedGame {
        frames = List.copyOf(frames);
        traces = List.copyOf(traces);
    }
}
