package org.scenes.simulator;

import java.nio.file.Path;
import java.util.List;

/**
 * How a simulated game ended.
 *
 * @param kicksLeft kicks that touched the ball, left team
 * @param steps simulator steps run, including pauses with the clock stopped
 * @param logs the player logs written, in team and uniform-number order
 */
public record GameResult(int scoreLeft, int scoreRight, int kicksLeft, int kicksRight, int cycles, int steps,
                         List<Path> logs) {
    public GameResult {
        logs = List.copyOf(logs);
    }
}
