package org.scenes.internal.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;

class VisionTableTest {
    @Test
    void cellsCountObjectsByKindWithFarRowOnTop() {
        Grid grid = Grid.DEFAULT;
        List<SeenObject> objects = List.of(
                SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 0.8, 1, grid),
                SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 40, 2, grid),
                SeenObject.simple(ObjectKind.FLAG, "f p r t", Relation.NONE, 30, 3, grid),
                SeenObject.simple(ObjectKind.FLAG, "f p r c", Relation.NONE, 35, -5, grid),
                SeenObject.simple(ObjectKind.PLAYER, "p", Relation.TEAMMATE, 3, -40, grid),
                SeenObject.simple(ObjectKind.PLAYER, "p", Relation.OPPONENT, 3.5, -30, grid),
                SeenObject.simple(ObjectKind.LINE, "l r", Relation.NONE, 36, 80, grid));
        Scene scene = new Scene(42, new Observer("Poland", Side.LEFT, 2), objects, List.of(Action.kick(100, 12)));

        String table = VisionTable.render(scene, grid);

        String expected = """
                Scene cycle 42  Poland 2 (l)
                Teammates/opponents/unknown players = 1/1/0
                +------+------+------+------+------+
                |      |      | G 2F |      |  1L  |
                +------+------+------+------+------+
                |  2P  |      |      |      |      |
                +------+------+------+------+------+
                |      |      |  B   |      |      |
                +------+------+------+------+------+
                action: kick power=100 direction=12
                """;
        assertEquals(expected, table);
    }
}
