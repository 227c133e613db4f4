package org.scenes.api;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class WorldTest {
    private static World at(double x, double y, double ballX, double ballY, List<World.Player> players) {
        return new World(x, y, 0, 0, 0, 0, 8000, 1, 0, ballX, ballY, 0, 0, 0, players, "play_on", 0, 0);
    }

    @Test
    void theBallsDistanceIsUnknownWithoutEitherPosition() {
        assertEquals(5, at(0, 0, 3, 4, List.of()).ballDistance(), 1e-12);
        assertTrue(Double.isNaN(at(Double.NaN, Double.NaN, 3, 4, List.of()).ballDistance()));
        assertTrue(Double.isNaN(at(0, 0, Double.NaN, Double.NaN, List.of()).ballDistance()));
    }

    @Test
    void thePlayerIsItsTeamsNearestToTheBallUnlessATeammateItKnowsIsNearer() {
        World.Player mate = new World.Player(Relation.TEAMMATE, 7, 3, 3, 0);
        World.Player opponent = new World.Player(Relation.OPPONENT, 7, 3, 4, 0);
        assertTrue(at(0, 0, 3, 4, List.of(opponent)).nearestOfItsTeamToBall(), "opponents do not count");
        assertFalse(at(0, 0, 3, 4, List.of(mate)).nearestOfItsTeamToBall());
        assertFalse(at(Double.NaN, Double.NaN, 3, 4, List.of()).nearestOfItsTeamToBall(), "unlocated");
    }
}
