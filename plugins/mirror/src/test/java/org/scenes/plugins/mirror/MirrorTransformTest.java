package org.scenes.plugins.mirror;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SceneTransform;
import org.scenes.api.SeenObject;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

class MirrorTransformTest {
    private static final Grid GRID = Grid.DEFAULT;

    private static Scene scene() {
        SeenObject ball = new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, 4, -30, 0.1, 2.5,
                Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, GRID.cell(4, -30));
        SeenObject post = SeenObject.simple(ObjectKind.FLAG, "f g r t", Relation.NONE, 40, 12, GRID);
        SeenObject flag = SeenObject.simple(ObjectKind.FLAG, "f b l 30", Relation.NONE, 50, 44, GRID);
        SeenObject line = SeenObject.simple(ObjectKind.LINE, "l t", Relation.NONE, 20, -80, GRID);
        SeenObject goal = SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 41, 10, GRID);
        return new Scene(7, Observer.UNKNOWN, List.of(ball, post, flag, line, goal),
                List.of(Action.kick(80, -20), Action.turnNeck(30)));
    }

    @Test
    void theMirrorNegatesDirectionsSwapsSidesAndMirrorsCommands() {
        Scene mirrored = Mirror.of(scene());
        SeenObject ball = mirrored.objects().get(0);
        assertEquals(30, ball.direction());
        assertEquals(-2.5, ball.directionChange());
        assertEquals(GRID.cell(4, 30), ball.cell());
        assertEquals(List.of("b", "f g r b", "f t l 30", "l b", "g r"),
                mirrored.objects().stream().map(SeenObject::name).toList());
        assertEquals(GRID.cell(50, -44), mirrored.objects().get(2).cell());
        assertEquals(List.of(Action.kick(80, 20), Action.turnNeck(-30)), mirrored.actions());
        assertEquals(Action.turn(-40), Mirror.mirror(Action.turn(40)));
        assertEquals(Action.move(-10, -5), Mirror.mirror(Action.move(-10, 5)));
        assertEquals(Action.dash(100), Mirror.mirror(Action.dash(100)), "a plain dash has no direction");
        assertEquals(scene(), Mirror.of(mirrored), "mirroring twice gives the scene back");
    }

    @Test
    void theKnowledgeBaseStoresBothWhileQueriesStayAsTheyAre() {
        SceneTransform mirror = PluginRegistry.load().transform("mirror", PluginConfig.DEFAULT);
        Scene original = scene();
        assertSame(original, mirror.apply(original));
        KnowledgeBase knowledge = KnowledgeBase.builder(GRID).addSequence(List.of(original), List.of(mirror)).build();
        assertEquals(List.of(original, Mirror.of(original)), knowledge.scenes());
        assertEquals(List.of(original, Mirror.of(original)), KnowledgeBase.stored(List.of(original), List.of(mirror)));
    }

    /** A player that turns to the ball, seen at each of these directions. */
    private static List<Scene> turnsToTheBall(double... directions) {
        List<Scene> scenes = new java.util.ArrayList<>();
        for (double direction : directions) {
            SeenObject ball = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 10, direction, GRID);
            scenes.add(new Scene(scenes.size(), Observer.UNKNOWN, List.of(ball), List.of(Action.turn(direction))));
        }
        return scenes;
    }

    @Test
    void matchingBothOrientationsFindsWhatStoringBothFinds() {
        SceneMetric ballDirection = (a, b) -> Math.abs(a.objects().get(0).direction() - b.objects().get(0).direction());
        List<Scene> scenes = turnsToTheBall(-40, -25, -10, 5, 18, 33);
        SceneTransform both = PluginRegistry.load().transform("mirror", PluginConfig.DEFAULT);
        SceneTransform match = PluginRegistry.load().transform("mirror:match", PluginConfig.DEFAULT);
        KnowledgeBase stored = KnowledgeBase.builder(GRID).addSequence(scenes, List.of(both)).build();
        KnowledgeBase alone = KnowledgeBase.builder(GRID).addSequence(scenes, List.of(match)).build();
        assertEquals(12, stored.size());
        assertEquals(6, alone.size(), "mirror:match stores the scenes alone");
        Recognizer storing = new Recognizer(stored, () -> ballDirection, 3);
        Recognizer matching = new Recognizer(alone, () -> ballDirection, 3,
                SceneTransform.queryImage(List.of(match)));
        // queries off the half degrees, so no two stored scenes or images are equally near
        for (Scene query : turnsToTheBall(-44.3, -37.3, -30.3, -23.3, -2.3, 4.7, 11.7, 25.7, 39.7)) {
            List<Neighbour> expected = storing.nearest(query);
            List<Neighbour> got = matching.nearest(query);
            assertEquals(expected.stream().map(Neighbour::distance).toList(), got.stream().map(Neighbour::distance).toList());
            assertEquals(expected.stream().map(n -> n.scene().actions()).toList(), got.stream().map(n -> n.scene().actions()).toList(),
                    "a scene found for the mirrored query comes back mirrored, its turn with it");
        }
        assertEquals(List.of(Action.turn(-5)), matching.nearest(turnsToTheBall(-4).get(0)).get(0).scene().actions());
    }

    @Test
    void refusesAnUnknownArgumentAndTwoQueryImages() {
        assertThrows(PluginException.class, () -> PluginRegistry.load().transform("mirror:both", PluginConfig.DEFAULT));
        SceneTransform match = PluginRegistry.load().transform("mirror:match", PluginConfig.DEFAULT);
        assertThrows(IllegalArgumentException.class, () -> SceneTransform.queryImage(List.of(match, match)));
    }
}
