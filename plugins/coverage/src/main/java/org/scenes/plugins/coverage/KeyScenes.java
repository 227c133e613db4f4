package org.scenes.plugins.coverage;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Supplier;
import org.scenes.match.KnowledgeBase;
import org.scenes.match.Neighbour;
import org.scenes.match.ObjectSetMetric;
import org.scenes.match.Recognizer;
import org.scenes.match.SceneMetric;
import org.scenes.scene.Grid;
import org.scenes.scene.Scene;

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

    /** The {@code top} scenes of most influence (fewer when fewer have any), most first. */
    public static List<Ranked> rank(Grid grid, List<Scene> scenes, Supplier<SceneMetric> metrics, int top) {
        int[] influence = new int[scenes.size()];
        if (scenes.size() > 2) {
            Recognizer recognizer = new Recognizer(KnowledgeBase.of(grid, scenes), metrics, 3);
            for (int i = 0; i < scenes.size(); i++) {
                List<Neighbour> others = new ArrayList<>(2);
                for (Neighbour neighbour : recognizer.nearest(scenes.get(i))) {
                    if (neighbour.index() != i && others.size() < 2) {
                        others.add(neighbour);
                    }
                }
                if (others.size() == 2 && ObjectSetMetric.actionClass(others.get(0).scene())
                        != ObjectSetMetric.actionClass(others.get(1).scene())) {
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
