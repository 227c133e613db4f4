package org.scenes.internal.inference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;

/** The server's models inverted on steps made by them (rcssserver 19's default parameters, no noise). */
class CommandInferenceTest {
    private final CommandInference inference = new CommandInference(new ServerModel());

    private static PlayerState player(Side side, double x, double y, double vx, double vy, double body, double neck,
                                      double stamina, PlayerState.Counts counts) {
        return new PlayerState(side, 7, 0, PlayerState.STANDING, x, y, vx, vy, body, neck, 'h', 90, stamina, 1, 1,
                Double.NaN, counts);
    }

    private static PlayerState.Counts counts(int kick, int dash, int turn, int move, int turnNeck) {
        return new PlayerState.Counts(kick, dash, turn, 0, move, turnNeck, 0, 0, 0, 0, 0);
    }

    private static GameFrame frame(int time, GameFrame.BallState ball, PlayerState player) {
        return new GameFrame(time, "play_on", "L", "R", 0, 0, ball, List.of(player));
    }

    private static final GameFrame.BallState STILL = new GameFrame.BallState(10, 10, 0, 0);

    private CommandInference.Step step(PlayerState a, PlayerState b, GameFrame.BallState ball, GameFrame.BallState next) {
        return inference.infer(frame(1, ball, a), a, frame(2, next, b), b);
    }

    @Test
    void aTurnIsTheBodysTurnTimesOnePlusInertiaTimesSpeed() {
        PlayerState a = player(Side.LEFT, 0, 0, 0.2, 0, 10, 0, 8000, counts(0, 0, 4, 0, 0));
        PlayerState b = player(Side.LEFT, 0.2, 0, 0.08, 0, 30, 0, 8000, counts(0, 0, 5, 0, 0));
        CommandInference.Step step = step(a, b, STILL, STILL);
        assertEquals(CommandType.TURN, step.body());
        // inertia_moment 5, speed 0.2: the moment is twice the turn
        assertEquals(40, step.commands().get(0).first(), 1e-9);
        assertEquals("(turn 40)", step.text());
    }

    @Test
    void aDashsPowerIsWhatTheStaminaLostBeyondItsRecovery() {
        // power 80 forward at effort 1: acceleration 80 * 0.006, decayed by 0.4; stamina 5000 - 80 + 45
        PlayerState a = player(Side.LEFT, 0, 0, 0, 0, 0, 0, 5000, counts(0, 3, 0, 0, 0));
        PlayerState b = player(Side.LEFT, 0.48, 0, 0.4 * 0.48, 0, 0, 0, 4965, counts(0, 4, 0, 0, 0));
        CommandInference.Command dash = step(a, b, STILL, STILL).commands().get(0);
        assertEquals(CommandType.DASH, dash.type());
        assertEquals(80, dash.first(), 1e-6);
        assertEquals(0, dash.second(), 1e-9);
    }

    @Test
    void atFullStaminaTheAccelerationTellsTheDashAndItsDirection() {
        // power 60 at 90 degrees: side_dash_rate 0.4 of it acts, towards y+ for a body at 0
        double accel = 60 * 0.4 * 0.006;
        PlayerState a = player(Side.LEFT, 0, 0, 0, 0, 0, 0, 8000, counts(0, 3, 0, 0, 0));
        PlayerState b = player(Side.LEFT, 0, accel, 0, 0.4 * accel, 0, 0, 8000, counts(0, 4, 0, 0, 0));
        CommandInference.Command dash = step(a, b, STILL, STILL).commands().get(0);
        assertEquals(60, dash.first(), 1e-6);
        assertEquals(90, dash.second(), 1e-9);
    }

    @Test
    void aKicksDirectionAndPowerComeFromTheBallsAcceleration() {
        PlayerState a = player(Side.LEFT, 0, 0, 0, 0, 0, 0, 8000, counts(2, 0, 0, 0, 0));
        PlayerState b = player(Side.LEFT, 0, 0, 0, 0, 0, 0, 8000, counts(3, 0, 0, 0, 0));
        double distance = 0.5 - 0.3 - 0.085;
        double rate = 0.027 * (1 - 0.25 * distance / 0.7);
        double accel = 50 * rate;
        double angle = Math.toRadians(30);
        GameFrame.BallState ball = new GameFrame.BallState(0.5, 0, 0, 0);
        GameFrame.BallState next = new GameFrame.BallState(0.5 + accel * Math.cos(angle), accel * Math.sin(angle),
                0.94 * accel * Math.cos(angle), 0.94 * accel * Math.sin(angle));
        CommandInference.Command kick = step(a, b, ball, next).commands().get(0);
        assertEquals(CommandType.KICK, kick.type());
        assertEquals(50, kick.first(), 1e-6);
        assertEquals(30, kick.second(), 1e-6);
        // rcssserver's noises: kick_rand 0.1 of the power share 0.5 times (0.5 + 0.25 distance / kickable_margin
        // for where the ball lay, plus 0.5 for a still ball), then ball_rand 0.05 of the new speed
        double noise = 0.1 * 0.5 * (0.5 + 0.25 * distance / 0.7 + 0.5) + 0.05 * accel;
        assertEquals(Math.toDegrees(Math.asin(noise / accel)), kick.secondBound(), 1e-9);
        assertEquals(noise / rate, kick.firstBound(), 1e-9);
    }

    @Test
    void aMoveIsThePositionAfterInThePlayersOwnCoordinatesAndTheNeckItsChange() {
        PlayerState a = player(Side.RIGHT, 0, 0, 0, 0, 180, 10, 8000, counts(0, 0, 0, 0, 1));
        PlayerState b = player(Side.RIGHT, 20, -5, 0, 0, 180, -30, 8000, counts(0, 0, 0, 1, 2));
        CommandInference.Step step = step(a, b, STILL, STILL);
        assertEquals("(move -20 5)(turn_neck -40)", step.text());
    }

    @Test
    void countersThatJumpOrGoBackAreReportedNotGuessed() {
        PlayerState a = player(Side.LEFT, 0, 0, 0, 0, 0, 0, 8000, counts(0, 3, 0, 0, 0));
        CommandInference.Step jump = step(a, player(Side.LEFT, 0, 0, 0, 0, 0, 0, 8000, counts(0, 5, 0, 0, 0)),
                STILL, STILL);
        assertNotNull(jump.irregular());
        assertTrue(jump.irregular().contains("dash count jumps by 2"), jump.irregular());
        assertTrue(jump.commands().isEmpty());
        CommandInference.Step back = step(a, player(Side.LEFT, 0, 0, 0, 0, 0, 0, 8000, counts(0, 2, 0, 0, 0)),
                STILL, STILL);
        assertTrue(back.irregular().contains("goes back"), back.irregular());
        CommandInference.Step none = step(a, a, STILL, STILL);
        assertNull(none.irregular());
        assertNull(none.body());
        assertEquals("", none.text());
    }
}
