package org.scenes.coverage;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Supplier;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.NearestScenes;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectKind;
import org.scenes.api.ObjectSetMetrics;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

/**
 * Key scenes: a scene matters as much as the predictions of other scenes that hang on it. For
 * every scene, its nearest other scene (with the configuration's metric) decides its predicted
 * action; when the second-nearest other scene carries another action class, removing the nearest
 * would change that prediction, and the nearest scores a point. Scenes are ranked by points,
 * ties by order.
 */
public final class KeyScenes {
    private KeyScenes() {
    }

    /** @param index where the scene is in the input, @param influence the predictions hanging on it */
    public record Ranked(int index, Scene scene, int influence) {
    }

    /**
     * Scenes of events, in order, at most {@code top}: the player kicks or moves (a move follows a
     * change of play mode: kick-off, goal), or the ball changes hands: the nearest player to
     * the ball (the observer itself when the ball is within 1 m) is another than in the scene
     * before. Influence is 1 for each event the scene holds.
     */
    public static List<Ranked> events(List<Scene> scenes, int top) {
        List<Ranked> found = new ArrayList<>();
        String holder = null;
        for (int i = 0; i < scenes.size() && found.size() < top; i++) {
            Scene scene = scenes.get(i);
            int events = scene.actionType() == ActionType.KICK || scene.actionType() == ActionType.MOVE ? 1 : 0;
            String now = holder(scene);
            if (now != null && holder != null && !now.equals(holder)) {
                events++;
            }
            if (now != null) {
                holder = now;
            }
            if (events > 0) {
                found.add(new Ranked(i, scene, events));
            }
        }
        return List.copyOf(found);
    }

    /** Who is nearest the ball in the scene, or null when the ball or every readable player is out of sight. */
    private static String holder(Scene scene) {
        SeenObject ball = null;
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL && !object.remembered() && !Double.isNaN(object.distance())) {
                ball = object;
                break;
            }
        }
        if (ball == null) {
            return null;
        }
        if (ball.distance() <= 1) {
            return "self";
        }
        String nearest = "self";
        double best = ball.distance();
        for (SeenObject object : scene.objects()) {
            if (object.kind() != ObjectKind.PLAYER || object.uniformNumber() == 0 || object.remembered()
                    || Double.isNaN(object.distance()) || Double.isNaN(object.direction())) {
                continue;
            }
            double gap = separation(ball, object);
            if (gap < best) {
                best = gap;
                nearest = object.identity();
            }
        }
        return nearest;
    }

    private static double separation(SeenObject a, SeenObject b) {
        double angle = Math.toRadians(a.direction() - b.direction());
        return Math.sqrt(Math.max(0, a.distance() * a.distance() + b.distance() * b.distance()
                - 2 * a.distance() * b.distance() * Math.cos(angle)));
    }

    /** The {@code top} scenes of most influence (fewer when fewer have any), most first. */
    public static List<Ranked> rank(Grid grid, List<Scene> scenes, Supplier<SceneMetric> metrics, int top) {
        int[] influence = new int[scenes.size()];
        if (scenes.size() > 2) {
            NearestScenes search = NearestScenes.of(grid, scenes, metrics, 3);
            for (int i = 0; i < scenes.size(); i++) {
                List<Neighbour> others = new ArrayList<>(2);
                for (Neighbour neighbour : search.nearest(scenes.get(i))) {
                    if (neighbour.index() != i && others.size() < 2) {
                        others.add(neighbour);
                    }
                }
                if (others.size() == 2 && ObjectSetMetrics.actionClass(others.get(0).scene())
                        != ObjectSetMetrics.actionClass(others.get(1).scene())) {
                    influence[others.get(0).index()]++;
                }
            }
        }
        List<Ranked> ranked = new ArrayList<>();
        for (int i = 0; i < scenes.size(); i++) {
            if (influence[i] > 0) {
                ranked.add(new Ranked(i, scenes.get(i), influence[i]));
            }
        }
        ranked.sort(Comparator.comparingInt(Ranked::influence).reversed().thenComparingInt(Ranked::index));
        return List.copyOf(ranked.subList(0, Math.min(top, ranked.size())));
    }
}
