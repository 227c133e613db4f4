package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.simulator.GameResult;

class GameFiguresTest {
    private static final MessageParser PARSER = new MessageParser();

    private static PlayerCommand command(String text) {
        return (PlayerCommand) PARSER.parse(text);
    }

    @Test
    void runsOfOneActionOnAnUnchangedViewAreStuckOnlyFromTwentyOn() {
        PlayerTrace trace = new PlayerTrace(1);
        // 25 dashes seeing the same thing: stuck; then 19 turns on one view: not stuck
        for (int i = 0; i < 25; i++) {
            trace.see(i, 42, false);
            trace.driverSent(command("(dash 100)"));
            trace.shadowSent(command("(dash 80)"));
        }
        for (int i = 25; i < 44; i++) {
            trace.see(i, 7, false);
            trace.driverSent(command("(turn 30)"));
            trace.shadowSent(command(i < 35 ? "(turn 10)" : "(turn -10)"));
        }
        // paused sees count for nothing
        for (int i = 44; i < 80; i++) {
            trace.see(i, 7, true);
            trace.driverSent(command("(turn 30)"));
        }
        // a see without an answer neither breaks nor extends a run
        trace.see(80, 7, false);
        trace.close();
        GameFigures figures = GameFigures.of(game(trace, List.of()));
        assertEquals(25, figures.dashes());
        assertEquals(19, figures.turns());
        assertEquals(25.0 / 44, figures.stuckShare(), 1e-12);
        assertEquals(44.0 / 45, figures.answered(), 1e-12);
        // turns agree in type always, in sign on the first 10 of 19
        assertEquals(1.0, figures.typeAgreement(), 1e-12);
        assertEquals((25.0 + 10) / 44, figures.agreement(), 1e-12);
    }

    @Test
    void firstTouchCountsCyclesFromKickOffToTheSidesFirstReachOfTheBall() {
        List<GameFrame> frames = new ArrayList<>();
        frames.add(frame(0, "before_kick_off", -20, 0));
        frames.add(frame(0, "kick_off_l", -20, 0));
        for (int t = 1; t <= 10; t++) {
            frames.add(frame(t, "play_on", -20 + 2 * t, 0)); // reaches the ball at (0, 0) on cycle 10
        }
        assertEquals(10, GameFigures.firstTouch(frames, Side.LEFT), 1e-12);
        assertEquals(Double.NaN, GameFigures.firstTouch(frames, Side.RIGHT));
        // play on only: the mean of 18, 16, ..., 0 metres
        assertEquals(9, GameFigures.ballDistance(frames, Side.LEFT), 1e-12);
    }

    private static GameFrame frame(int time, String mode, double x, double y) {
        PlayerState player = new PlayerState(Side.LEFT, 1, 0, PlayerState.STANDING, x, y, 0, 0, 0, 0, 'h', 90, 8000, 1, 1,
                Double.NaN, new PlayerState.Counts(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
        return new GameFrame(time, mode, "Teal", "Amber", 0, 0, new GameFrame.BallState(0, 0, 0, 0), List.of(player));
    }

    private static PlayedGame game(PlayerTrace trace, List<GameFrame> frames) {
        return new PlayedGame(PlayedGame.Role.IMITATOR, Side.LEFT, 1, new GameResult(2, 1, 3, 4, 1000, 1100, List.of()),
                frames, List.of(trace));
    }
}
