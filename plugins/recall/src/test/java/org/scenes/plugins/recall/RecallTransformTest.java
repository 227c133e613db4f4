package org.scenes.plugins.recall;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.SeenObject;

class RecallTransformTest {
    private static final Grid GRID = Grid.DEFAULT;

    private static SeenObject ball(double distance, double direction, double distChange, double dirChange) {
        return new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, distance, direction, distChange,
                dirChange, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, GRID.cell(distance, direction));
    }

    private static final SeenObject FLAG = flag(0);

    /** The centre flag, 30 m away: as the player turns by m, its direction changes by -m. */
    private static SeenObject flag(double direction) {
        return SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, 30, direction, GRID);
    }

    private static Scene scene(int cycle, Action action, SeenObject... objects) {
        return new Scene(cycle, Observer.UNKNOWN, List.of(objects), List.of(action));
    }

    private static SceneTransform recall(String spec) {
        return PluginRegistry.load().transform(spec, PluginConfig.DEFAULT);
    }

    private static SeenObject rememberedBall(Scene scene) {
        return scene.objects().stream().filter(o -> o.kind() == ObjectKind.BALL).findFirst().orElseThrow();
    }

    @Test
    void aBallLeavingTheViewIsCarriedAlongTheTurnsAndForgottenAfterTheHorizon() {
        SceneTransform recall = recall("recall:3");
        Scene seen = recall.apply(scene(10, Action.turn(-10), ball(10, 40, 0, 2), FLAG));
        assertEquals(2, seen.objects().size(), "nothing to remember yet");
        assertFalse(rememberedBall(seen).remembered());
        // one cycle later: +2 of its own, +10 because the player turned 10 to the left
        Scene first = recall.apply(scene(11, Action.turn(-10), flag(10)));
        SeenObject ball = rememberedBall(first);
        assertTrue(ball.remembered());
        assertEquals(52, ball.direction(), 1e-9);
        assertEquals(10, ball.distance(), 1e-9);
        assertEquals(GRID.cell(10, 52), ball.cell());
        assertEquals(1 - 2 / 5.0, ball.confidence(), 1e-12);
        Scene second = recall.apply(scene(12, Action.dash(100), flag(20)));
        assertEquals(64, rememberedBall(second).direction(), 1e-9);
        assertTrue(rememberedBall(second).confidence() < ball.confidence(), "confidence falls with age");
        // the dash moves the player 0.6 m ahead: the ball, to its side, ends a little farther back
        SeenObject third = rememberedBall(recall.apply(scene(13, Action.turn(0), flag(20))));
        assertTrue(third.direction() > 66, "direction " + third.direction());
        assertEquals(1 / 5.0, third.confidence(), 1e-12);
        assertEquals(1, recall.apply(scene(14, Action.turn(0), flag(20))).objects().size(), "past the horizon");
    }

    @Test
    void theLandmarksSayWhetherTheCommandedTurnHasHappenedYet() {
        SceneTransform recall = recall("recall:5");
        recall.apply(scene(1, Action.turn(-10), ball(10, 50, 0, 0), flag(0)));
        // the command has not taken effect by the next see: the flag has not moved, nor has the ball
        assertEquals(50, rememberedBall(recall.apply(scene(2, Action.turn(0), flag(0)))).direction(), 1e-9);
        // it has by the one after
        assertEquals(60, rememberedBall(recall.apply(scene(3, Action.turn(-20), flag(10)))).direction(), 1e-9);
        // no landmark in both scenes: the commanded turn is all there is
        assertEquals(80, rememberedBall(recall.apply(scene(4, Action.turn(0)))).direction(), 1e-9);
        assertEquals(20, ObjectMemory.observedTurn(scene(5, Action.turn(0), flag(-5), SeenObject.simple(ObjectKind.GOAL, "g r",
                Relation.NONE, 50, 30, GRID)), scene(6, Action.turn(0), flag(-25), SeenObject.simple(ObjectKind.GOAL, "g r",
                Relation.NONE, 50, 10, GRID))), 1e-9);
    }

    @Test
    void aRememberedObjectBackInTheViewConeButNotSeenIsForgotten() {
        SceneTransform recall = recall("recall");
        recall.apply(scene(1, Action.turn(0), ball(20, 50, 0, 0)));
        assertTrue(rememberedBall(recall.apply(scene(2, Action.turn(40)))).remembered());
        // 50 - 40 = 10: inside the view, yet not reported, so the ball is not there
        Scene afterTurn = recall.apply(scene(3, Action.turn(0)));
        assertEquals(List.of(), afterTurn.objects(), "the turn of 40 brings it to 10 degrees");
    }

    @Test
    void aSeenObjectIsNeverDoubledAndANewSequenceForgetsEverything() {
        SceneTransform recall = recall("recall");
        SeenObject sideFlag = SeenObject.simple(ObjectKind.FLAG, "f t 10", Relation.NONE, 30, 70, GRID);
        recall.apply(scene(5, Action.turn(0), ball(10, 60, 0, 0), sideFlag));
        Scene again = recall.apply(scene(6, Action.turn(0), ball(9, 60, 0, 0)));
        assertEquals(2, again.objects().size(), "the ball once, seen; the flag remembered");
        assertFalse(again.objects().get(0).remembered());
        assertTrue(again.objects().get(1).remembered());
        assertEquals(1, recall.apply(scene(2, Action.turn(0), ball(9, 60, 0, 0))).objects().size(),
                "the cycle went back: a new sequence");
    }

    @Test
    void badHorizonsAndOtherGridsAreRefusedClearly() {
        assertThrows(PluginException.class, () -> recall("recall:0"));
        assertThrows(PluginException.class, () -> recall("recall:soon"));
        Grid fine = Grid.of(7, 1, 5, 20);
        SeenObject odd = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 3, 30, fine);
        IllegalArgumentException error = assertThrows(IllegalArgumentException.class,
                () -> recall("recall").apply(scene(1, Action.turn(0), odd)));
        assertTrue(error.getMessage().contains("default grid"), error.getMessage());
    }
}
