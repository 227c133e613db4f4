package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.scenes.api.Side;

class PhysicsTest {
    private final World world = new World(ServerParams.DEFAULT, 3);
    private final Physics physics = new Physics(world);
    private final Player player = world.add("Teal", Side.LEFT, 1);

    PhysicsTest() {
        world.mode = PlayMode.PLAY_ON;
        player.place(0, 0);
        player.body = 0;
        world.ball.place(20, 20);
    }

    @Test
    void dashAcceleratesAlongTheBodyThenDecays() {
        physics.dash(player, 100);
        physics.step();
        // a = 100 * 0.006 * effort 1 = 0.6; noise at most player_rand * 0.6 per axis
        assertEquals(0.6, player.x, 0.06 + 1e-9);
        assertEquals(0, player.y, 0.06 + 1e-9);
        assertEquals(0.4 * player.x, player.vx, 1e-9);
        assertEquals(8000 - 100, player.stamina, 1e-9);
    }

    @Test
    void dashPowerIsCappedAtMaxpower() {
        physics.dash(player, 603);
        assertEquals(0.6, player.ax, 1e-9);
    }

    @Test
    void dashBeforeKickOffCostsStaminaButDoesNotMove() {
        world.mode = PlayMode.BEFORE_KICK_OFF;
        physics.dash(player, 100);
        physics.step();
        assertEquals(0, player.x);
        assertEquals(7900, player.stamina, 1e-9);
    }

    @Test
    void turnIsSlowedBySpeed() {
        // The server scales each turn by a random factor within player_rand (10 %) of 1.
        physics.turn(player, 90);
        assertEquals(90, player.body, 9 + 1e-9);
        player.body = 0;
        player.vx = 0.5;
        physics.turn(player, 90);
        assertEquals(90 / (1 + 5 * 0.5), player.body, 0.1 * 90 / (1 + 5 * 0.5) + 1e-9);
    }

    @Test
    void turnsVaryLikeTheServers() {
        double least = 180;
        double most = 0;
        for (int i = 0; i < 200; i++) {
            player.body = 0;
            physics.turn(player, 50);
            least = Math.min(least, player.body);
            most = Math.max(most, player.body);
        }
        assertTrue(least >= 45 && least < 46 && most <= 55 && most > 54, least + " to " + most);
    }

    @Test
    void kickOnlyWithinKickableDistance() {
        world.ball.place(2, 0);
        assertFalse(physics.kick(player, 100, 0));
        assertEquals(0, world.ball.ax);
        world.ball.place(0.5, 0);
        assertTrue(physics.kick(player, 100, 0));
        // 100 * 0.027 * (1 - 0.25 * gap / 0.7), gap = 0.5 - 0.385; noise up to kick_rand times the
        // placement rate (0.5 + 0.25 * gap / 0.7) plus the speed rate (0.5 for a ball at rest)
        double expected = 2.7 * (1 - 0.25 * (0.5 - 0.385) / 0.7);
        assertEquals(expected, world.ball.ax, 0.1 * (1 + 0.25 * 0.115 / 0.7) + 1e-9);
    }

    @Test
    void ballSpeedIsCappedAndDecays() {
        world.ball.place(10, 10);
        world.ball.vx = 5;
        physics.step();
        assertEquals(13, world.ball.x, 3 * 0.05 + 1e-9);
        assertEquals(0.94 * (world.ball.x - 10), world.ball.vx, 1e-9);
    }

    @Test
    void moveMirrorsTheRightSide() {
        Player right = world.add("Amber", Side.RIGHT, 2);
        physics.move(right, -10, 5);
        assertEquals(10, right.x);
        assertEquals(-5, right.y);
    }

    @Test
    void overlappingPlayersArePushedApart() {
        Player other = world.add("Amber", Side.RIGHT, 2);
        other.place(0.2, 0);
        physics.step();
        assertEquals(0.6, player.distanceTo(other), 1e-9);
        assertEquals(0.1, (player.x + other.x) / 2, 1e-9); // both moved by half the overlap
    }

    @Test
    void inPlayABallAndAPlayerBothGiveWayOutsideOnlyThePlayer() {
        world.ball.place(0.185, 0);
        physics.step();
        assertEquals(0.385, player.distanceTo(world.ball), 1e-9);
        assertEquals(0.0925, (player.x + world.ball.x) / 2, 1e-9);
        world.mode = PlayMode.KICK_OFF;
        player.place(0, 0);
        world.ball.place(0.185, 0);
        physics.step();
        assertEquals(0.185, world.ball.x, 1e-9);
        assertEquals(0.385, player.distanceTo(world.ball), 1e-9);
    }

    @Test
    void aBallInsideAPlayerBouncesOut() {
        world.ball.place(0.1, 0.01);
        world.ball.vx = -0.05; // rolling into the player
        physics.step();
        assertEquals(0.385, player.distanceTo(world.ball), 1e-9);
        assertTrue(world.ball.vx > 0, "bounced back");
    }

    @Test
    void staminaRecoversEachCycle() {
        player.stamina = 7000;
        physics.recover(player);
        assertEquals(7045, player.stamina, 1e-9);
    }
}
