package org.scenes.internal.scene;

import java.util.List;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;

/** Scenes holding every object kind, relation, optional field and action type. */
final class SceneFixtures {
    static final Observer OBSERVER = new Observer("Carleton", Side.LEFT, 3);

    private SceneFixtures() {
    }

    static List<Scene> everyKind(Grid grid) {
        SeenObject ball = new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, 2.7, -5, -0.1, 3.2,
                Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, grid.cell(2.7, -5));
        SeenObject goal = SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 106.7, -16, grid);
        SeenObject ownGoal = SeenObject.simple(ObjectKind.GOAL, "G", Relation.OWN, 2.5, 170, grid);
        SeenObject flag = SeenObject.simple(ObjectKind.FLAG, "f p r b", Relation.NONE, 86.5, -6, grid);
        SeenObject line = SeenObject.simple(ObjectKind.LINE, "l r", Relation.NONE, 36.2, 90, grid);
        SeenObject teammate = new SeenObject(ObjectKind.PLAYER, "p", "Carleton", 7, true, Relation.TEAMMATE,
                10.5, -20, 0.2, -1, 45, 30, 12, 't', grid.cell(10.5, -20));
        SeenObject opponent = new SeenObject(ObjectKind.PLAYER, "p", "University", 0, false, Relation.OPPONENT,
                36.6, -13, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, 'k', grid.cell(36.6, -13));
        SeenObject unknown = SeenObject.simple(ObjectKind.PLAYER, "p", Relation.UNKNOWN, 60.3, -28, grid);
        SeenObject behind = SeenObject.simple(ObjectKind.PLAYER, "P", Relation.UNKNOWN, 3, -117, grid);
        SeenObject directionOnly = SeenObject.simple(ObjectKind.FLAG, "f r t", Relation.NONE, Double.NaN, -31, grid);
        List<SeenObject> all = List.of(ball, goal, ownGoal, flag, line, teammate, opponent, unknown, behind, directionOnly);
        Observer other = new Observer("University", Side.RIGHT, 5);
        return List.of(
                new Scene(1, OBSERVER, all, List.of(Action.dash(100))),
                new Scene(2, OBSERVER, all, List.of(Action.dash(80, -30), Action.turnNeck(20))),
                new Scene(3, OBSERVER, List.of(ball), List.of(Action.kick(100, -12.5))),
                new Scene(4, OBSERVER, List.of(), List.of(Action.turn(40))),
                new Scene(5, other, List.of(goal), List.of(Action.catchBall(-30))),
                new Scene(6, OBSERVER, List.of(flag), List.of(Action.move(-49.826, 28.93))),
                new Scene(7, OBSERVER, List.of(flag), List.of(Action.tackle(50))),
                new Scene(8, OBSERVER, List.of(flag), List.of(Action.turnNeck(-90))),
                new Scene(9, OBSERVER, List.of(line), List.of()));
    }
}
