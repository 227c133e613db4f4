package org.scenes.plugins.mirror;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.match.KnowledgeBase;
import org.scenes.match.SceneTransform;
import org.scenes.plugin.PluginConfig;
import org.scenes.plugin.PluginRegistry;
import org.scenes.scene.Action;
import org.scenes.scene.Grid;
import org.scenes.scene.ObjectKind;
import org.scenes.scene.Observer;
import org.scenes.scene.Relation;
import org.scenes.scene.Scene;
import org.scenes.scene.SeenObject;

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
}
