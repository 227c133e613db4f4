package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/** Possessions from frames: a team's kicks until the other team's kick or a stop of play. */
class PossessionsTest {
    /**
     * Frames of times 1 to 12, a left and a right player whose kick counters rise in the frames of
     * the times given; from {@code stopAt} on, play is stopped (0: never).
     */
    private static List<GameFrame> frames(int[] leftKicks, int[] rightKicks, int stopAt) {
        List<GameFrame> frames = new ArrayList<>();
        for (int t = 1; t <= 12; t++) {
            int time = t;
            int left = (int) Arrays.stream(leftKicks).filter(k -> k <= time).count();
            int right = (int) Arrays.stream(rightKicks).filter(k -> k <= time).count();
            String mode = stopAt > 0 && t >= stopAt ? "kick_in_r" : "play_on";
            frames.add(new GameFrame(t, mode, "Teal", "Amber", 0, 0, new GameFrame.BallState(0, 0, 0, 0),
                    List.of(player(Side.LEFT, left), player(Side.RIGHT, right))));
        }
        return frames;
    }

    private static PlayerState player(Side side, int kicks) {
        return new PlayerState(side, 4, 0, PlayerState.STANDING, side == Side.LEFT ? -1 : 1, 0, 0, 0, 0, 0, 'h', 90,
                8000, 1, 1, Double.NaN, new PlayerState.Counts(kicks, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
    }

    private static int[] at(int... times) {
        return times;
    }

    @Test
    void aPossessionLastsFromTheTeamsFirstKickToTheOtherTeamsNext() {
        List<GameFrame> frames = frames(at(2, 4), at(7, 9), 0);
        assertEquals(new Possessions(1, 5, 2), Possessions.of(frames, Side.LEFT));
        assertEquals(new Possessions(0, Double.NaN, Double.NaN), Possessions.of(frames, Side.RIGHT),
                "the log's end cut the right's");
        assertEquals(new Possessions(2, 3, 1.5), Possessions.of(frames(at(2, 4, 10), at(7, 11), 0), Side.LEFT),
                "two of the left's: 5 cycles and 2 kicks, 1 cycle and 1 kick");
    }

    @Test
    void aStopOfPlayOrAStepWhereBothKickedEndsIt() {
        assertEquals(new Possessions(1, 3, 1), Possessions.of(frames(at(2), at(), 5), Side.LEFT), "the ball out at 5");
        List<GameFrame> both = frames(at(2, 3), at(3, 6), 9);
        assertEquals(new Possessions(1, 1, 1), Possessions.of(both, Side.LEFT), "both kicked at 3");
        assertEquals(new Possessions(1, 3, 1), Possessions.of(both, Side.RIGHT),
                "the right's began at its kick of 6, not at the shared step");
        assertTrue(Double.isNaN(Possessions.of(frames(at(), at(), 0), Side.LEFT).meanCycles()));
    }
}
