package org.scenes.internal.target;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;

class DestinationsTest {
    private static final Observer SEVEN = new Observer("T", Side.LEFT, 7);
    private static final Observer EIGHT = new Observer("T", Side.LEFT, 8);

    private static Scene at(Observer observer, int cycle, double x, double y, double ballX, double ballY, String mode,
                            Action action) {
        World world = new World(x, y, 0, 0, 0, 0, 8000, 1, 0, ballX, ballY, 0, 0, 0, List.of(), mode, 0, 0);
        return new Scene(cycle, observer, List.of(), List.of(action), null, 0, world);
    }

    /** A player running along x one metre a cycle from {@code x0}, the ball far away. */
    private static List<Scene> run(Observer observer, int cycles, double x0, double y) {
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < cycles; t++) {
            scenes.add(at(observer, t, x0 + t, y, 40, 30, "play_on", Action.dash(100)));
        }
        return scenes;
    }

    private static Neighbour neighbour(int index) {
        return new Neighbour(null, index, 0);
    }

    @Test
    void aNearNeighbourLendsItsEndPointAFarOneItsDisplacement() {
        List<Scene> scenes = run(SEVEN, 20, 0, 0);
        Destinations destinations = Destinations.of(scenes);
        World here = at(SEVEN, 0, 3, 4, 40, 30, "play_on", Action.dash(100)).world();
        // scene 0 stood at (0, 0), 5 m away: its end point, (10, 0)
        assertArrayEquals(new double[] {10, 0}, destinations.target(List.of(neighbour(0)), here, null), 1e-9);
        World far = at(SEVEN, 0, -30, 20, 40, 30, "play_on", Action.dash(100)).world();
        // 36 m away: its displacement, 10 m along x
        assertArrayEquals(new double[] {-20, 20}, destinations.target(List.of(neighbour(0)), far, null), 1e-9);
        // two neighbours: the mean
        assertArrayEquals(new double[] {10.5, 0}, destinations.target(List.of(neighbour(0), neighbour(1)), here, null),
                1e-9);
    }

    @Test
    void aNeighbourNearItsBallLendsItsEndPointRelativeToTheBallPlacedAtTheOwnBall() {
        // a player 5 m behind its ball at (5, 0) runs along x to (10, 0): 5 m past where the ball was
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < 20; t++) {
            scenes.add(at(SEVEN, t, t, 0, 5, 0, "play_on", Action.dash(100)));
        }
        Destinations destinations = Destinations.of(scenes);
        // the deciding player near the neighbour, its ball at (-20, 10): the run answers the ball
        World here = at(SEVEN, 0, 3, 4, -20, 10, "play_on", Action.dash(100)).world();
        assertArrayEquals(new double[] {-15, 10}, destinations.target(List.of(neighbour(0)), here, null), 1e-9);
        // without a ball of its own: the end point, as for any near neighbour
        World blind = at(SEVEN, 0, 3, 4, Double.NaN, Double.NaN, "play_on", Action.dash(100)).world();
        assertArrayEquals(new double[] {10, 0}, destinations.target(List.of(neighbour(0)), blind, null), 1e-9);
    }

    @Test
    void aPlayerThatRemembersFollowsAMovingAverageOfItsNeighboursDestinations() {
        List<Scene> scenes = new ArrayList<>(run(SEVEN, 20, 0, 0));
        scenes.addAll(run(EIGHT, 20, 0, 6));
        Destinations destinations = Destinations.of(scenes);
        World here = at(SEVEN, 0, 3, 3, 40, 30, "play_on", Action.dash(100)).world();
        Steering steering = new Steering();
        // neighbours whose end points alternate between (10, 0) and (10, 6): the spot moves part way
        assertArrayEquals(new double[] {10, 0}, destinations.target(List.of(neighbour(0)), here, null, steering), 1e-9);
        double[] next = destinations.target(List.of(neighbour(20)), here, null, steering);
        assertArrayEquals(new double[] {10, 6 * Steering.NEW_DESTINATION}, next, 1e-9);
        double[] back = destinations.target(List.of(neighbour(0)), here, null, steering);
        assertEquals(6 * Steering.NEW_DESTINATION * (1 - Steering.NEW_DESTINATION), back[1], 1e-9);
        // a player that does not remember takes each mean as it is
        assertArrayEquals(new double[] {10, 6}, destinations.target(List.of(neighbour(20)), here, null), 1e-9);
    }

    @Test
    void theTeachersOwnChaseRateInThatRaceDecidesWhereEnoughOfItsScenesStoodSo() {
        // forty recorded players, each 2.5 m behind a still ball, ran through it; one ran on far from its ball
        List<Scene> scenes = new ArrayList<>();
        for (int p = 0; p < 40; p++) {
            Observer player = new Observer("T" + p, Side.LEFT, 7);
            for (int t = 0; t < 12; t++) { // a destination for the scenes of cycles 0 and 1 only
                scenes.add(at(player, t, t, 3 * p - 60, 2.5, 3 * p - 60, "play_on", Action.dash(100)));
            }
        }
        scenes.addAll(run(EIGHT, 20, 0, 10));
        Destinations destinations = Destinations.of(scenes);
        assertEquals(1.0, destinations.chaseRate(new BallRace(3, BallRace.Standing.FIRST)), 1e-9,
                "all forty, 3 cycles from their still ball, reached it");
        assertEquals(Double.NaN, destinations.chaseRate(new BallRace(3, BallRace.Standing.TEAMMATE_FIRST)),
                "no scene of a player with a faster teammate");
        assertEquals(Double.NaN, destinations.chaseRate(new BallRace(45, BallRace.Standing.FIRST)),
                "one run is too few to tell");
        // a neighbour that ran on without the ball: the rate, not the neighbour, sends the player to its ball
        World here = at(SEVEN, 0, 0, 10, 2, 11, "play_on", Action.dash(100)).world();
        double[] ball = {2, 11};
        assertArrayEquals(ball, destinations.target(List.of(neighbour(480)), here, ball, new Steering()), 1e-9);
        World far = at(SEVEN, 0, 0, 10, 40, 30, "play_on", Action.dash(100)).world();
        assertArrayEquals(new double[] {10, 10}, destinations.target(List.of(neighbour(480)), far, ball, new Steering()),
                1e-9, "no rate that far: the neighbours' share");
    }

    @Test
    void labelsAddedToAKnowledgeBaseLendNoDestinationAndTakeNoneFromThePlayedScenes() {
        List<Scene> played = run(SEVEN, 20, 0, 0);
        // the imitator's scenes labelled by its shadow: a run on, as if played after the recorded one
        List<Scene> labels = run(SEVEN, 40, 0, 0).subList(20, 40);
        KnowledgeBase base = KnowledgeBase.of(Grid.DEFAULT, played);
        KnowledgeBase labelled = base.plus(List.of(labels), List::of);
        assertEquals(20, labelled.played());
        assertEquals(40, labelled.size());
        World here = played.get(0).world();
        Destinations destinations = Destinations.of(labelled);
        assertNull(destinations.target(List.of(neighbour(20)), here, null), "a label's next scenes are not its play");
        // the last played scenes do not run on into the labels
        assertNull(destinations.target(List.of(neighbour(15)), here, null));
        assertNotNull(Destinations.of(KnowledgeBase.of(Grid.DEFAULT, run(SEVEN, 30, 0, 0)))
                .target(List.of(neighbour(15)), here, null), "the same scenes, all played, have destinations");
        assertArrayEquals(new double[] {10, 0}, destinations.target(List.of(neighbour(0)), here, null), 1e-9);
        // a played scene and a label dropped: the labels stay labels
        KnowledgeBase fewer = labelled.without(scene -> scene.cycle() == 3 || scene.cycle() == 25);
        assertEquals(19, fewer.played());
        assertEquals(38, fewer.size());
        assertSame(labelled, labelled.without(scene -> false));
    }

    @Test
    void noDestinationAcrossAnotherPlayerAPlayModeAMoveOrTheEndOfItsScenes() {
        List<Scene> scenes = new ArrayList<>(run(SEVEN, 8, 0, 0));
        scenes.addAll(run(EIGHT, 20, 0, 0)); // another player follows: scene 0 of number 7 has no tenth cycle
        scenes.add(at(SEVEN, 30, 0, 0, 40, 30, "play_on", Action.dash(100)));
        for (int t = 31; t < 45; t++) {
            scenes.add(at(SEVEN, t, t - 30, 0, 40, 30, t < 35 ? "play_on" : "goal_l", Action.dash(100)));
        }
        Destinations destinations = Destinations.of(scenes);
        World here = scenes.get(0).world();
        assertNull(destinations.target(List.of(neighbour(0)), here, null));
        assertNull(destinations.target(List.of(neighbour(28)), here, null)); // the play mode changes at cycle 35
        List<Scene> moved = new ArrayList<>(run(SEVEN, 20, 0, 0));
        moved.set(5, at(SEVEN, 5, -20, 0, 40, 30, "play_on", Action.move(-20, 0)));
        assertNull(Destinations.of(moved).target(List.of(neighbour(0)), here, null));
        assertNull(destinations.target(List.of(neighbour(0)), null, null));
    }

    @Test
    void runsEndInsideTheFieldLines() {
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < 20; t++) {
            scenes.add(at(SEVEN, t, t, 0, 5, 0, "play_on", Action.dash(100)));
        }
        Destinations destinations = Destinations.of(scenes);
        // a chase after a ball rolling into the own goal stops a metre before the goal line
        World defender = at(SEVEN, 0, -45, 2, -50, 1, "play_on", Action.dash(100)).world();
        assertArrayEquals(new double[] {-51.5, 3}, destinations.target(List.of(neighbour(0)), defender,
                new double[] {-56, 3}), 1e-9);
        // a far neighbour's displacement (10 m along x) from beside the side line, the ball unknown
        World winger = at(SEVEN, 0, 48, 33.5, Double.NaN, Double.NaN, "play_on", Action.dash(100)).world();
        assertArrayEquals(new double[] {51.5, 33}, destinations.target(List.of(neighbour(0)), winger, null), 1e-9);
    }

    @Test
    void whenMostNeighboursReachedTheBallThePlayerRunsToItsOwnBall() {
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < 20; t++) {
            // the ball rests at (5, 0): the player passes it at cycle 5
            scenes.add(at(SEVEN, t, t, 0, 5, 0, "play_on", Action.dash(100)));
        }
        scenes.addAll(run(EIGHT, 20, 0, 10));
        Destinations destinations = Destinations.of(scenes);
        World here = scenes.get(0).world();
        double[] ball = {7, 7};
        assertArrayEquals(ball, destinations.target(List.of(neighbour(0), neighbour(1)), here, ball), 1e-9);
        // one of three ran to the ball: the mean end point
        assertArrayEquals(new double[] {10, 10 * 2 / 3.0},
                destinations.target(List.of(neighbour(0), neighbour(20), neighbour(20)), here, ball), 1e-9);
        // no ball known: the mean end point too
        assertArrayEquals(new double[] {10.5, 0}, destinations.target(List.of(neighbour(0), neighbour(1)), here, null),
                1e-9);
    }

    @Test
    void aPlayerThatReachedTheBallWithinTheChaseWindowRanToIt() {
        // the ball rests at (25, 0): the player reaches it at cycle 24, past the destination's
        // ten cycles but within the chase window; one resting at (45, 0) is reached too late
        List<Scene> near = new ArrayList<>();
        List<Scene> far = new ArrayList<>();
        for (int t = 0; t < 50; t++) {
            near.add(at(SEVEN, t, t, 0, 25, 0, "play_on", Action.dash(100)));
            far.add(at(SEVEN, t, t, 0, 45, 0, "play_on", Action.dash(100)));
        }
        World here = near.get(0).world();
        double[] ball = {7, 7};
        assertArrayEquals(ball, Destinations.of(near).target(List.of(neighbour(0)), here, ball), 1e-9);
        assertArrayEquals(new double[] {10, 0}, Destinations.of(far).target(List.of(neighbour(0)), here, ball), 1e-9);
    }

    @Test
    void aChaseGoesOnWhileAThirdOfTheNeighboursRanToTheBall() {
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < 20; t++) {
            scenes.add(at(SEVEN, t, t, 0, 5, 0, "play_on", Action.dash(100))); // passes its ball at cycle 5
        }
        scenes.addAll(run(EIGHT, 20, 0, 10)); // runs on, the ball far away
        Destinations destinations = Destinations.of(scenes);
        World here = scenes.get(0).world();
        double[] ball = {7, 7};
        List<Neighbour> twoOfThree = List.of(neighbour(0), neighbour(1), neighbour(20));
        List<Neighbour> oneOfTwo = List.of(neighbour(0), neighbour(20));
        List<Neighbour> oneOfFour = List.of(neighbour(0), neighbour(20), neighbour(21), neighbour(22));
        Steering steering = new Steering();
        // one of two does not start a chase
        assertArrayEquals(new double[] {10, 5}, destinations.target(oneOfTwo, here, ball, steering), 1e-9);
        assertArrayEquals(ball, destinations.target(twoOfThree, here, ball, steering), 1e-9);
        // but keeps one going, until fewer than a third ran to the ball
        assertArrayEquals(ball, destinations.target(oneOfTwo, here, ball, steering), 1e-9);
        double[] spot = destinations.target(oneOfFour, here, ball, steering);
        assertNotEquals(ball[0], spot[0]);
        // a spot again: the moving average from the first spot after the chase, towards (10, 5)
        double[] next = destinations.target(oneOfTwo, here, ball, steering);
        assertArrayEquals(new double[] {spot[0] + Steering.NEW_DESTINATION * (10 - spot[0]),
            spot[1] + Steering.NEW_DESTINATION * (5 - spot[1])}, next, 1e-9);
    }
}
