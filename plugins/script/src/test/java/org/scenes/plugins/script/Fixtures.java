package org.scenes.plugins.script;

import java.util.ArrayList;
import java.util.List;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;

/** Small synthetic scenes for script tests. */
final class Fixtures {
    static final Observer OBSERVER = new Observer("Carleton", Side.LEFT, 3);

    private Fixtures() {
    }

    static SeenObject ball(double distance, double direction) {
        return SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT);
    }

    static SeenObject opponentGoal(double distance, double direction) {
        return SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, distance, direction, Grid.DEFAULT);
    }

    static SeenObject flag(double distance, double direction) {
        return SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, distance, direction, Grid.DEFAULT);
    }

    static Scene scene(int cycle, Action action, SeenObject... objects) {
        List<Action> actions = new ArrayList<>();
        if (action != null) {
            actions.add(action);
        }
        return new Scene(cycle, OBSERVER, List.of(objects), actions);
    }
}
