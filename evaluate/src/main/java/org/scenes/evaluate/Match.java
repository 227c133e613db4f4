package org.scenes.evaluate;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.IntConsumer;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;

/** One game between two teams, both traced, each with an optional shadow brain beside its players. */
public final class Match {
    /** The game as each side played it. */
    public record Outcome(PlayedGame left, PlayedGame right) {
    }

    private Match() {
    }

    public static Outcome play(GameSetup.Team left, BrainFactory leftShadow, GameSetup.Team right,
                               BrainFactory rightShadow, int cycles, long seed, Arena arena, IntConsumer progress)
            throws IOException {
        List<PlayerTrace> leftTraces = new ArrayList<>();
        List<PlayerTrace> rightTraces = new ArrayList<>();
        GameSetup setup = new GameSetup(
                new GameSetup.Team(left.name(), left.players(), Evaluation.traced(left.brains(), leftShadow, seed, leftTraces)),
                new GameSetup.Team(right.name(), right.players(),
                        Evaluation.traced(right.brains(), rightShadow, seed + 7919, rightTraces)),
                cycles, seed, null);
        List<GameFrame> frames = new ArrayList<>();
        GameResult result = arena.play(setup, progress, frames::add);
        leftTraces.forEach(PlayerTrace::close);
        rightTraces.forEach(PlayerTrace::close);
        return new Outcome(new PlayedGame(leftShadow == null ? PlayedGame.Role.TEACHER : PlayedGame.Role.IMITATOR,
                Side.LEFT, seed, result, frames, leftTraces),
                new PlayedGame(rightShadow == null ? PlayedGame.Role.TEACHER : PlayedGame.Role.IMITATOR, Side.RIGHT, seed,
                        result, frames, rightTraces));
    }
}
