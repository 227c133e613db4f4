package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;

class RefereeTest {
    private final World world = new World(ServerParams.DEFAULT, 1);
    private final Referee referee = new Referee(world, 6000, new Physics(world));
    private final Player left = world.add("Teal", Side.LEFT, 1);
    private final Player right = world.add("Amber", Side.RIGHT, 1);

    RefereeTest() {
        world.mode = PlayMode.PLAY_ON;
        world.time = 100;
        left.place(-10, 0);
        right.place(10, 0);
    }

    @Test
    void kickOffAfterTheWaitAtTimeZero() {
        world.mode = PlayMode.BEFORE_KICK_OFF;
        world.time = 0;
        for (int i = 0; i < Referee.BEFORE_KICK_OFF_STEPS; i++) {
            referee.endStep();
        }
        assertEquals(List.of("(hear 0 referee kick_off_l)"), referee.takeAnnouncements());
        assertEquals(0, world.time);
        assertTrue(referee.mayKick(left));
        assertFalse(referee.mayKick(right));
        referee.ballKicked(left);
        assertEquals(List.of("(hear 0 referee play_on)"), referee.takeAnnouncements());
    }

    @Test
    void goalStopsTheClockThenTheOtherSideKicksOff() {
        world.ball.place(53, 2);
        referee.endStep();
        assertEquals(List.of("(hear 100 referee goal_l_1)"), referee.takeAnnouncements());
        assertEquals(1, world.scoreLeft);
        for (int i = 0; i < Referee.PAUSE_STEPS; i++) {
            referee.endStep();
        }
        assertEquals(100, world.time);
        assertEquals(List.of("(hear 100 referee kick_off_r)"), referee.takeAnnouncements());
        assertEquals(0, world.ball.x);
    }

    @Test
    void afterAGoalTheBallStaysAndAtTheKickOffPlayersStandInTheirOwnHalf() {
        left.place(40, 20);
        right.place(4, 1);
        world.ball.place(53, 2);
        referee.endStep();
        assertEquals(53, world.ball.x, "the ball stays where it crossed");
        for (int i = 0; i < Referee.PAUSE_STEPS; i++) {
            referee.endStep();
        }
        // The left player was in the other half: back to its side of the halfway line, same y.
        assertEquals(-0.3, left.x, 1e-9);
        assertEquals(20, left.y, 1e-9);
        // The right kicks off: its player may stand in the centre circle.
        assertEquals(4, right.x, 1e-9);
    }

    @Test
    void ballOverTheTouchLineIsAKickInForTheOtherSide() {
        world.lastTouch = Side.LEFT;
        world.ball.place(20, 34.5);
        referee.endStep();
        assertEquals(List.of("(hear 100 referee kick_in_r)"), referee.takeAnnouncements());
        assertEquals(34, world.ball.y);
        assertFalse(referee.mayKick(left));
        assertTrue(referee.mayKick(right));
    }

    @Test
    void ballOverTheGoalLineIsAGoalKickOrACorner() {
        world.lastTouch = Side.LEFT;
        world.ball.place(53, 20);
        referee.endStep();
        assertEquals(List.of("(hear 100 referee goal_kick_r)"), referee.takeAnnouncements());
        assertEquals(47, world.ball.x, 1e-9);
        world.mode = PlayMode.PLAY_ON;
        world.lastTouch = Side.RIGHT;
        world.ball.place(53, -20);
        referee.endStep();
        assertEquals(List.of("(hear 101 referee corner_kick_l)"), referee.takeAnnouncements());
        assertEquals(51.5, world.ball.x, 1e-9);
        assertEquals(-33, world.ball.y, 1e-9);
    }

    @Test
    void theOtherSideKeepsItsDistanceAndTheBallIsDroppedWhenNobodyKicks() {
        world.lastTouch = Side.LEFT;
        right.place(21, 33);
        world.ball.place(20, 34.5);
        referee.endStep(); // kick-in for the right: the left keeps away
        left.place(19, 33);
        referee.endStep();
        assertEquals(Referee.KEEP_AWAY + 0.3, left.distanceTo(world.ball), 1e-9); // and a player's size
        assertTrue(right.distanceTo(world.ball) < 2, "the side taking it may come close");
        referee.takeAnnouncements();
        for (int i = 1; i < Referee.DROP_BALL_TIME; i++) {
            referee.endStep();
        }
        List<String> said = referee.takeAnnouncements();
        assertEquals(2, said.size());
        assertTrue(said.get(0).endsWith("referee drop_ball)"), said.toString());
        assertEquals(PlayMode.PLAY_ON, world.mode);
    }

    @Test
    void halfTimeAndTimeOver() {
        world.time = 2999;
        referee.endStep();
        assertEquals(List.of("(hear 3000 referee half_time)", "(hear 3000 referee before_kick_off)"),
                referee.takeAnnouncements());
        assertEquals(PlayMode.BEFORE_KICK_OFF, world.mode);
        assertTrue(right.x > 0, "in its own half");
        for (int i = 0; i < Referee.BEFORE_KICK_OFF_STEPS; i++) {
            referee.endStep();
        }
        assertEquals(List.of("(hear 3000 referee kick_off_r)"), referee.takeAnnouncements());
        world.time = 5999;
        referee.endStep();
        assertEquals(List.of("(hear 6000 referee time_over)"), referee.takeAnnouncements());
        assertEquals(PlayMode.TIME_OVER, world.mode);
    }
}
