package org.scenes.plugins.history;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;

/**
 * Scenes shaped like a librcsc player's on synchronous vision: a body command and a
 * {@code turn_neck} every cycle, a see every other cycle (see age 0, 1), plans that last several
 * cycles (turn to the target, then dash; wait with {@code (turn 0)}; scan: turn on a fresh see,
 * nothing in between). What the player does next follows from the plan under way, not from
 * what it sees: the ball is drawn at random.
 */
final class Synthetic {
    static final Observer OBSERVER = new Observer("Teacher", Side.LEFT, 7);

    private Synthetic() {
    }

    static Scene scene(int cycle, int age, double ballDistance, Action body, Action neck) {
        List<SeenObject> objects = List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, ballDistance, 0, Grid.DEFAULT));
        List<Action> actions = neck == null ? List.of(body) : List.of(body, neck);
        return new Scene(cycle, OBSERVER, objects, actions, null, age);
    }

    /** One player's game of {@code cycles} cycles. */
    static List<Scene> game(long seed, int cycles) {
        Random random = new Random(seed);
        List<Action> plan = new ArrayList<>();
        List<Scene> scenes = new ArrayList<>(cycles);
        for (int cycle = 1; cycle <= cycles; cycle++) {
            int age = cycle % 2;
            if (plan.isEmpty()) {
                plan.addAll(nextPlan(random, age));
            }
            Action body = plan.remove(0);
            Action neck = Action.turnNeck(random.nextInt(3) == 0 ? 0 : random.nextInt(120) - 60);
            scenes.add(scene(cycle, age, 1 + random.nextDouble() * 40, body, neck));
        }
        return scenes;
    }

    private static List<Action> nextPlan(Random random, int age) {
        List<Action> plan = new ArrayList<>();
        switch (random.nextInt(3)) {
            case 0 -> { // go to a point: a full turn, a small one, then a run
                plan.add(Action.turn(180));
                plan.add(Action.turn(20 + random.nextInt(40)));
                int dashes = 3 + random.nextInt(3);
                for (int i = 0; i < dashes; i++) {
                    plan.add(Action.dash(80 + random.nextInt(20)));
                }
            }
            case 1 -> { // wait
                int waits = 2 + random.nextInt(3);
                for (int i = 0; i < waits; i++) {
                    plan.add(Action.turn(0));
                }
            }
            default -> { // scan: turn with each fresh see, nothing in between
                for (int i = 0; i < 4; i++) {
                    plan.add((age + i) % 2 == 0 ? Action.turn(90) : Action.turn(0));
                }
            }
        }
        return plan;
    }
}
