package org.scenes.internal.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;

class SceneOperationsTest {
    private static final Grid GRID = Grid.DEFAULT;
    private static final SeenObject BALL = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 3, 10, GRID);
    private static final SeenObject GOAL = SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 40, -5, GRID);
    private static final SeenObject FLAG = SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, 20, 30, GRID);
    private static final SeenObject MATE_7 = new SeenObject(ObjectKind.PLAYER, "p", "Carleton", 7, false,
            Relation.TEAMMATE, 8, 2, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK,
            GRID.cell(8, 2));
    private static final SeenObject MATE_9 = new SeenObject(ObjectKind.PLAYER, "p", "Carleton", 9, false,
            Relation.TEAMMATE, 8, 2, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK,
            GRID.cell(8, 2));

    private static Scene scene(int cycle, SeenObject... objects) {
        return new Scene(cycle, SceneFixtures.OBSERVER, List.of(objects), List.of(Action.turn(cycle)));
    }

    @Test
    void unionKeepsThisScenesObjectsAndAddsTheOthersNewOnes() {
        SeenObject ballElsewhere = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 9, -40, GRID);
        Scene now = scene(2, BALL, MATE_7);
        Scene earlier = scene(1, ballElsewhere, GOAL, MATE_9, GOAL);
        Scene union = now.union(earlier);
        assertEquals(List.of(BALL, MATE_7, GOAL, MATE_9), union.objects(), "this scene's ball wins; the goal once");
        assertEquals(2, union.cycle());
        assertEquals(Action.turn(2), union.primaryAction());
        assertEquals(List.of(ballElsewhere, GOAL, MATE_9, GOAL, MATE_7), earlier.union(now).objects(),
                "the other way round adds only teammate 7");
    }

    @Test
    void intersectionAndDifferenceSplitThisScenesObjects() {
        Scene now = scene(2, BALL, FLAG, MATE_7);
        Scene earlier = scene(1, FLAG, MATE_9, GOAL);
        assertEquals(List.of(FLAG), now.intersection(earlier).objects());
        assertEquals(List.of(BALL, MATE_7), now.difference(earlier).objects(), "teammates 7 and 9 are different players");
        assertEquals(List.of(MATE_9, GOAL), earlier.difference(now).objects());
        // every object of a scene is in exactly one of intersection and difference
        assertEquals(now.objects().size(),
                now.intersection(earlier).objects().size() + now.difference(earlier).objects().size());
        assertEquals(List.of(), now.difference(now).objects());
        assertEquals(now, now.intersection(now));
        assertEquals(now, now.union(scene(5)));
    }
}
