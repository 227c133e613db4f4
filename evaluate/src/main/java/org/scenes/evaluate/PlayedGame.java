package org.scenes.evaluate;

import java.util.List;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.simulator.GameResult;

/**
 * One game seen from one side: who played there, which side it was, the seed, the result, the
 * world after every step, each of that side's players' traces (none for a game read from logs)
 * and the body commands its players executed (from the server's command log, or from the frames'
 * counters).
 */
public record PlayedGame(Role role, Side side, long seed, GameResult result, List<GameFrame> frames,
                         List<PlayerTrace> traces, ExecutedCommands executed) {
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
        if (executed == null) {
            executed = ExecutedCommands.fromCounters(frames, side);
        }
    }

    /** A game whose executed commands are read from the frames' counters. */
    public PlayedGame(Role role, Side side, long seed, GameResult result, List<GameFrame> frames,
                      List<PlayerTrace> traces) {
        this(role, side, seed, result, frames, traces, null);
    }

    /** The name of the side's team, from the last frame; empty without frames. */
    public String team() {
        if (frames.isEmpty()) {
            return "";
        }
        GameFrame last = frames.get(frames.size() - 1);
        return side == Side.LEFT ? last.leftTeam() : last.rightTeam();
    }
}
