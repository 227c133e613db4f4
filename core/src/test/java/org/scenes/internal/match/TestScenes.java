package org.scenes.internal.match;

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

/** Synthetic scenes for matching tests. */
public final class TestScenes {
    public static final Observer OBSERVER = new Observer("Test", Side.LEFT, 1);

    private TestScenes() {
    }

    public static SeenObject ball(double distance, double direction) {
        return SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT);
    }

    public static SeenObject goal(double distance, double direction) {
        return SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, distance, direction, Grid.DEFAULT);
    }

    public static SeenObject ownGoal(double distance, double direction) {
        return SeenObject.simple(ObjectKind.GOAL, "g l", Relation.OWN, distance, direction, Grid.DEFAULT);
    }

    public static SeenObject flag(double distance, double direction) {
        return SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, distance, direction, Grid.DEFAULT);
    }

    public static SeenObject player(Relation relation, double distance, double direction) {
        return new SeenObject(ObjectKind.PLAYER, "p", "", 0, false, relation, distance, direction, 0.1, -0.5,
                Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, Grid.DEFAULT.cell(distance, direction));
    }

    public static Scene scene(int cycle, Action action, SeenObject... objects) {
        return new Scene(cycle, OBSERVER, List.of(objects), action == null ? List.of() : List.of(action));
    }

    /** A Krislet-like scene: with the ball far at direction 0 it dashes, elsewhere turns, near it kicks. */
    public static Scene krislet(int cycle, double ballDistance, double ballDirection, double goalDirection) {
        Action action;
        if (ballDistance <= 1) {
            action = Action.kick(100, goalDirection);
        } else if (ballDirection == 0) {
            action = Action.dash(10 * ballDistance);
        } else {
            action = Action.turn(ballDirection);
        }
        return scene(cycle, action, ball(ballDistance, ballDirection), goal(40, goalDirection));
    }

    /** Random scenes with a varying number of objects of every class, for property checks. */
    public static List<Scene> random(long seed, int count) {
        Random random = new Random(seed);
        Relation[] relations = {Relation.TEAMMATE, Relation.OPPONENT, Relation.UNKNOWN};
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            List<SeenObject> objects = new ArrayList<>();
            if (random.nextBoolean()) {
                objects.add(ball(0.2 + random.nextDouble() * 60, random.nextInt(91) - 45));
            }
            if (random.nextBoolean()) {
                objects.add(goal(1 + random.nextDouble() * 80, random.nextInt(91) - 45));
            }
            for (int f = random.nextInt(5); f > 0; f--) {
                objects.add(flag(1 + random.nextDouble() * 90, random.nextInt(91) - 45));
            }
            for (int p = random.nextInt(5); p > 0; p--) {
                objects.add(player(relations[random.nextInt(3)], 0.5 + random.nextDouble() * 50, random.nextInt(91) - 45));
            }
            Action action = switch (random.nextInt(3)) {
                case 0 -> Action.dash(random.nextInt(100));
                case 1 -> Action.turn(random.nextInt(91) - 45);
                default -> Action.kick(100, random.nextInt(91) - 45);
            };
            Scene scene = new Scene(i, OBSERVER, objects, List.of(action));
            scenes.add(i > 0 && random.nextBoolean() ? scene.withPrevious(scenes.get(i - 1)) : scene);
        }
        return scenes;
    }
}
