package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/** Loose balls from frames: who was nearest to a slow free ball, and who kicked it next. */
class LooseBallsTest {
    /**
     * Twelve frames: a left player {@code leftAt} metres and a right player 5 m from a ball rolling
     * at {@code speed}; from frame {@code kickAt} on, the kick counter of the {@code kicker} side's
     * player is one up (0: nobody kicks); from frame {@code stopAt} on, play is stopped (0: never).
     */
    private static List<GameFrame> frames(double leftAt, double speed, Side kicker, int kickAt, int stopAt) {
        List<GameFrame> frames = new ArrayList<>();
        for (int t = 1; t <= 12; t++) {
            int leftKicks = kicker == Side.LEFT && kickAt > 0 && t >= kickAt ? 1 : 0;
            int rightKicks = kicker == Side.RIGHT && kickAt > 0 && t >= kickAt ? 1 : 0;
            String mode = stopAt > 0 && t >= stopAt ? "kick_in_r" : "play_on";
            frames.add(new GameFrame(t, mode, "Teal", "Amber", 0, 0, new GameFrame.BallState(0, 0, speed, 0),
                    List.of(player(Side.LEFT, -leftAt, leftKicks), player(Side.RIGHT, 5, rightKicks))));
        }
        return frames;
    }

    private static PlayerState player(Side side, double x, int kicks) {
        return new PlayerState(side, 4, 0, PlayerState.STANDING, x, 0, 0, 0, 0, 0, 'h', 90, 8000, 1, 1, Double.NaN,
                new PlayerState.Counts(kicks, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
    }

    @Test
    void aSlowBallNearestToThePlayerIsPlayedWhenItsTeamKicksNext() {
        assertEquals(new LooseBalls(1, 1), LooseBalls.of(frames(2, 0.5, Side.LEFT, 4, 0), Side.LEFT));
        assertEquals(new LooseBalls(1, 0), LooseBalls.of(frames(2, 0.5, Side.RIGHT, 4, 0), Side.LEFT),
                "the opponent got there first");
        assertEquals(new LooseBalls(0, 0), LooseBalls.of(frames(2, 0.5, Side.RIGHT, 4, 0), Side.RIGHT),
                "the right player was not the nearest");
        assertEquals(new LooseBalls(1, 0), LooseBalls.of(frames(2, 0.5, null, 0, 0), Side.LEFT),
                "nobody kicked within ten cycles: let roll");
        assertEquals(new LooseBalls(1, 0), LooseBalls.of(frames(2, 0.5, Side.LEFT, 12, 0), Side.LEFT),
                "its kick came after the ten cycles");
    }

    @Test
    void onlyASlowBallOutOfReachAndStillInPlayCounts() {
        assertEquals(new LooseBalls(0, 0), LooseBalls.of(frames(2, 1.5, Side.LEFT, 4, 0), Side.LEFT), "rolling fast");
        assertEquals(new LooseBalls(0, 0), LooseBalls.of(frames(0.8, 0.5, Side.LEFT, 4, 0), Side.LEFT),
                "within kicking reach already");
        assertEquals(new LooseBalls(0, 0), LooseBalls.of(frames(4, 0.5, Side.LEFT, 4, 0), Side.LEFT), "farther than 3 m");
        assertEquals(new LooseBalls(0, 0), LooseBalls.of(frames(2, 0.5, null, 0, 5), Side.LEFT),
                "play stopped before anyone kicked: no chance");
        assertTrue(Double.isNaN(new LooseBalls(0, 0).share()));
        assertEquals(0.5, new LooseBalls(4, 2).share(), 1e-12);
    }
}
