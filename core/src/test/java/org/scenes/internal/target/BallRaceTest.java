package org.scenes.internal.target;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Relation;
import org.scenes.api.World;

class BallRaceTest {
    /** A player at the origin; the ball 10 m ahead rolling towards it at 1 m a cycle. */
    private static World world(List<World.Player> players) {
        return new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, 10, 0, -1, 0, 0, players, "play_on", 0, 0);
    }

    @Test
    void theCyclesFollowTheBallsCourseAndTheRunAfterOneTurn() {
        BallRace race = BallRace.of(world(List.of()));
        // ball at 10 - (1 - 0.94^t) / 0.06 after t cycles; the player reaches (t - 1) + 1.085 m
        int expected = 0;
        double ball = 10;
        double speed = 1;
        while (ball > Math.max(0, expected - 1) + 1.085) {
            ball -= speed;
            speed *= 0.94;
            expected++;
        }
        assertEquals(new BallRace(expected, BallRace.Standing.FIRST), race);
        assertEquals(6, expected, "they meet 4.8 m from the player, after one turn and five metres of run");
    }

    @Test
    void aFasterTeammateOrOpponentItKnowsOfBeatsIt() {
        World.Player mate = new World.Player(Relation.TEAMMATE, 8, 9, 1, 0);
        World.Player opponent = new World.Player(Relation.OPPONENT, 4, 9, -1, 3);
        World.Player unknown = new World.Player(Relation.UNKNOWN, 0, 10, 0, 0);
        World.Player slowMate = new World.Player(Relation.TEAMMATE, 6, -20, 0, 0);
        assertEquals(BallRace.Standing.TEAMMATE_FIRST, BallRace.of(world(List.of(opponent, mate))).standing());
        assertEquals(BallRace.Standing.OPPONENT_FIRST, BallRace.of(world(List.of(opponent, slowMate))).standing());
        assertEquals(BallRace.Standing.FIRST, BallRace.of(world(List.of(unknown, slowMate))).standing(),
                "a player of unknown team is in nobody's race");
    }

    @Test
    void noRaceWithoutAPositionOrABall() {
        assertNull(BallRace.of(null));
        assertNull(BallRace.of(new World(Double.NaN, Double.NaN, 0, 0, 0, 0, 8000, 1, 0, 10, 0, 0, 0, 0, List.of(),
                "play_on", 0, 0)));
        assertNull(BallRace.of(new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, -1, List.of(),
                "play_on", 0, 0)));
    }
}
