package org.scenes.internal.target;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;

class FormationTest {
    private static final Observer PLAYER = new Observer("HELIOS", Side.LEFT, 2);
    private static final List<Action> TURN_AWAY = List.of(Action.turn(90), Action.turnNeck(20));

    /** A recorded scene of a player at ({@code x}, {@code y}) with its ball at ({@code ballX}, {@code ballY}). */
    private static Scene recorded(double x, double y, double ballX, double ballY, String mode) {
        World world = new World(x, y, 0, 0, 0, 0, 8000, 1, 0, ballX, ballY, 0, 0, 0, List.of(), mode, 0, 0);
        return new Scene(1, PLAYER, List.of(), List.of(Action.dash(100)), null, 0, world);
    }

    /**
     * A defender that stood 4 m goal-side of a ball in its half, and at (-20, 0) with the ball near the
     * centre spot: ten scenes each, spread over one square of ball positions.
     */
    private static Formation defender() {
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            scenes.add(recorded(-34 - 0.1 * i, 10, -30 - 0.1 * i, 10, "play_on"));
            scenes.add(recorded(-20, 0, 0.5, 0.5, "play_on"));
            scenes.add(recorded(40, 30, 30, 30, "free_kick_l")); // not play on: no spot
        }
        scenes.add(recorded(0, 0, 30, -30, "play_on")); // one scene: too few
        return Formation.of(scenes);
    }

    /** The deciding player at ({@code x}, 0) facing +x, its ball at (-30, 10), with {@code players} around. */
    private static World own(double x, String mode, List<World.Player> players) {
        return new World(x, 0, 0, 0, 0, 0, 8000, 1, 0, -30, 10, 0, 0, 0, players, mode, 0, 0);
    }

    /** An opponent at the ball: it reaches the ball before the deciding player. */
    private static final List<World.Player> OPPONENT_AT_BALL = List.of(new World.Player(Relation.OPPONENT, 9, -30.5, 10, 0));

    @Test
    void aSpotIsTheMeanPositionOverTheBallsSquareAndItsNeighboursInPlayOn() {
        Formation formation = defender();
        assertArrayEquals(new double[] {-34.45, 10}, formation.spot(-30, 10), 1e-9);
        assertArrayEquals(new double[] {-20, 0}, formation.spot(1, -1), 1e-9, "a neighbouring square");
        assertNull(formation.spot(30, 30), "only a set play was recorded there");
        assertNull(formation.spot(30, -30), "one scene is too few");
        assertNull(formation.spot(-50, -30), "nothing recorded near");
    }

    @Test
    void aPlayerFarUpfieldOfItsSpotRunsThereKeepingItsGazeUntilTwoMetresNear() {
        Formation formation = defender();
        List<Action> kept = formation.keep(TURN_AWAY, own(-10, "play_on", OPPONENT_AT_BALL), 100);
        assertEquals(ActionType.TURN, kept.get(0).type(), "the spot lies behind: a turn towards it first");
        assertEquals(Action.turnNeck(20), kept.get(1));
        World facingTheSpot = new World(-31, 9, 180 - Math.toDegrees(Math.atan2(1, 3.45)), 0, 0, 0, 8000, 1, 0, -30, 10,
                0, 0, 0, OPPONENT_AT_BALL, "play_on", 0, 0);
        assertEquals(Action.dash(100), formation.keep(TURN_AWAY, facingTheSpot, 100).get(0),
                "within 5 m but on its way: the run goes on");
        World there = new World(-33, 9.5, 180, 0, 0, 0, 8000, 1, 0, -30, 10, 0, 0, 0, OPPONENT_AT_BALL, "play_on", 0, 0);
        assertSame(TURN_AWAY, formation.keep(TURN_AWAY, there, 100), "within 2 m: the run ends");
        assertSame(TURN_AWAY, formation.keep(TURN_AWAY, facingTheSpot, 100), "and starts again only beyond 5 m");
        assertEquals(2, formation.runs());
    }

    @Test
    void noRunWhenThePlayerGoesForTheBallAKickIsChosenOrPlayIsStopped() {
        Formation formation = defender();
        assertSame(TURN_AWAY, formation.keep(TURN_AWAY, own(-10, "play_on", List.of()), 100),
                "nobody it knows of is nearer the ball: it goes for it");
        List<Action> kick = List.of(Action.kick(50, 0));
        assertSame(kick, formation.keep(kick, own(-10, "play_on", OPPONENT_AT_BALL), 100));
        assertSame(TURN_AWAY, formation.keep(TURN_AWAY, own(-10, "kick_in_r", OPPONENT_AT_BALL), 100));
        World atTheBall = new World(-30.5, 10, 0, 0, 0, 0, 8000, 1, 0, -30, 10, 0, 0, 0, OPPONENT_AT_BALL, "play_on", 0, 0);
        assertSame(TURN_AWAY, formation.keep(TURN_AWAY, atTheBall, 100), "the ball within its reach");
        World noBall = new World(-10, 0, 0, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, Double.NaN, Double.NaN, -1,
                OPPONENT_AT_BALL, "play_on", 0, 0);
        assertSame(TURN_AWAY, formation.keep(TURN_AWAY, noBall, 100));
        assertEquals(0, formation.runs());
    }
}
