package org.scenes.internal.target;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;

class BallWatchTest {
    private static final Observer SEVEN = new Observer("T", Side.LEFT, 7);

    /** A player at the centre facing along x, head straight, at rest, its ball at (ballX, ballY) seen ballAge cycles ago. */
    private static World world(double ballX, double ballY, int ballAge) {
        return new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, ballX, ballY, 0, 0, ballAge, List.of(), "play_on", 0, 0);
    }

    private static Scene scene(int ballAge, String mode) {
        World world = new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, 10, 0, 0, 0, ballAge, List.of(), mode, 0, 0);
        return new Scene(0, SEVEN, List.of(), List.of(Action.dash(100)), null, 0, world);
    }

    /** A watch whose teacher saw its ball at most {@code limit} cycles before in every play-on scene. */
    private static BallWatch watchOf(int limit) {
        List<Scene> scenes = new ArrayList<>();
        for (int age = 0; age <= limit; age++) {
            scenes.add(scene(age, "play_on"));
        }
        return BallWatch.of(scenes);
    }

    @Test
    void theLimitIsTheAgeThatNineteenOfTwentyPlayOnScenesDidNotExceed() {
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < 95; i++) {
            scenes.add(scene(i % 3, "play_on"));
        }
        for (int i = 0; i < 5; i++) {
            scenes.add(scene(40, "play_on"));
            scenes.add(scene(90, "free_kick_l")); // set plays do not count
        }
        assertEquals(2, BallWatch.of(scenes).limit());
        scenes.add(scene(40, "play_on"));
        assertEquals(40, BallWatch.of(scenes).limit());
    }

    @Test
    void scenesWithoutABallInPlayNeverOverrule() {
        BallWatch never = BallWatch.of(List.of(scene(3, "kick_off_l")));
        List<Action> chosen = List.of(Action.dash(100), Action.turnNeck(-30));
        assertSame(chosen, never.watch(chosen, world(0, 10, 500)));
    }

    @Test
    void aBallOlderThanTheLimitTurnsTheHeadToItInPlaceOfTheChosenGaze() {
        BallWatch watch = watchOf(2);
        List<Action> chosen = List.of(Action.dash(100), Action.turnNeck(-30));
        assertSame(chosen, watch.watch(chosen, world(10, 10, 2)), "a ball seen two cycles ago is fresh enough");

        List<Action> watched = watch.watch(chosen, world(10, 10, 3));
        assertEquals(2, watched.size());
        assertEquals(Action.dash(100), watched.get(0));
        assertEquals(ActionType.TURN_NECK, watched.get(1).type());
        assertEquals(45, watched.get(1).first(), 1e-9);
    }

    @Test
    void theHeadLooksFromWhereTheBodyWillFaceAndNoFurtherThanTheNeckGoes() {
        BallWatch watch = watchOf(2);
        // the body turns by 30 (at rest the whole moment): the ball at 45 is then 15 off
        List<Action> turning = watch.watch(List.of(Action.turn(30)), world(10, 10, 5));
        assertEquals(List.of(Action.turn(30), Action.turnNeck(15)), roundedNeck(turning));
        // a ball behind: the head turns as far as it goes, to the ball's side
        List<Action> behind = watch.watch(List.of(Action.dash(100)), world(-10, -2, 5));
        assertEquals(-90, behind.get(1).first(), 1e-9);
    }

    @Test
    void onlyABallBehindTheReachOfNeckAndViewAsksForAWiderView() {
        BallWatch watch = watchOf(2);
        List<Action> dash = List.of(Action.dash(100));
        assertTrue(watch.beyondView(dash, world(-10, -1, 5), 60), "at 174 degrees");
        assertFalse(watch.beyondView(dash, world(-10, -1, 1), 60), "seen a cycle ago");
        assertFalse(watch.beyondView(dash, world(-1, 10, 5), 60), "at 96 degrees, within 90 of the neck and 30 of the view");
        assertTrue(watch.beyondView(dash, world(-10, 5, 5), 60), "at 153 degrees");
        assertFalse(watch.beyondView(dash, world(-10, 5, 5), 180), "a wide view reaches it");
        assertFalse(watch.beyondView(List.of(Action.turn(180)), world(-10, -1, 5), 60), "the body turns to it");
    }

    @Test
    void aPlayerWithoutABallTurnsItsBodyWithTheHeadStraightToLookForIt() {
        World lost = new World(-40, -20, -141, 30, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, -1, List.of(),
                "play_on", 0, 0);
        List<Action> chosen = List.of(Action.dash(100), Action.turnNeck(0));
        List<Action> searched = BallWatch.search(chosen, lost);
        assertEquals(2, searched.size());
        assertEquals(ActionType.TURN, searched.get(0).type());
        assertEquals(BallWatch.SEARCH_TURN, searched.get(0).first(), 1e-9, "at rest a turn's moment is its angle");
        assertEquals(Action.turnNeck(-30), searched.get(1));
    }

    @Test
    void aSearchTurnsFurtherAtSpeedAndLeavesAStraightHeadAlone() {
        // moving at 0.2 m a cycle: the moment is 60 x (1 + 5 x 0.2)
        World running = new World(0, 0, 0, 0, 0.2, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, -1, List.of(),
                "play_on", 0, 0);
        assertEquals(List.of(Action.turn(120)), BallWatch.search(List.of(Action.dash(100)), running));
    }

    @Test
    void noSearchWithABallKnownNoPositionOrNoBallInPlay() {
        List<Action> chosen = List.of(Action.dash(100));
        assertSame(chosen, BallWatch.search(chosen, world(10, 10, 40)), "a ball known, however old");
        World unlocated = new World(Double.NaN, Double.NaN, 0, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, -1,
                List.of(), "play_on", 0, 0);
        assertSame(chosen, BallWatch.search(chosen, unlocated));
        for (String mode : List.of("before_kick_off", "goal_l", "goal_r", "time_over")) {
            World placing = new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, -1, List.of(),
                    mode, 0, 0);
            assertSame(chosen, BallWatch.search(chosen, placing), mode);
        }
        World freeKick = new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, -1, List.of(),
                "free_kick_r", 0, 0);
        List<Action> move = List.of(Action.move(-10, 0));
        assertSame(move, BallWatch.search(move, freeKick), "a placement stands");
        assertEquals(ActionType.TURN, BallWatch.search(chosen, freeKick).get(0).type());
    }

    private static List<Action> roundedNeck(List<Action> actions) {
        return List.of(actions.get(0), Action.turnNeck(Math.round(actions.get(1).first())));
    }
}
