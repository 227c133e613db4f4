package org.scenes.coverage;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.scenes.api.EncodedMetric;
import org.scenes.api.Grid;
import org.scenes.api.NearestScenes;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectSetMetrics;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

/**
 * Scene coverage: keeps the stored scenes that decide something. Two classic rules, both with the
 * configuration's metric and an action's class as the label (its type, turns split by sign):
 * <ul>
 * <li><b>editing</b> (Wilson): a scene whose {@code editK} nearest other scenes mostly carry
 *     another class is dropped as noise;</li>
 * <li><b>condensing</b> (Hart): starting from the first scene, every scene whose nearest kept
 *     scene carries another class is kept; passes repeat until one keeps nothing more, so at
 *     the end every dropped scene's nearest kept scene carries its class.</li>
 * </ul>
 * Scenes keep their order. Deterministic: ties go to the earlier scene.
 */
public final class Condenser {
    private final Supplier<SceneMetric> metrics;
    private final int editK;

    /** @param editK neighbours consulted when editing; 0 to skip editing */
    public Condenser(Supplier<SceneMetric> metrics, int editK) {
        if (editK < 0) {
            throw new IllegalArgumentException("the editing k is 0 (no editing) or more, not " + editK);
        }
        this.metrics = metrics;
        this.editK = editK;
    }

    /**
     * @param scenes the kept scenes in order
     * @param edited scenes dropped by editing
     * @param passes condensing passes over the scenes
     */
    public record Result(List<Scene> scenes, int edited, int passes) {
    }

    public Result condense(Grid grid, List<Scene> scenes) {
        if (scenes.isEmpty()) {
            throw new IllegalArgumentException("nothing to condense: no scenes");
        }
        List<Scene> edited = editK == 0 ? scenes : edit(grid, scenes);
        int removed = scenes.size() - edited.size();
        if (edited.isEmpty()) {
            edited = scenes;
            removed = 0;
        }
        return condensed(edited, removed);
    }

    private List<Scene> edit(Grid grid, List<Scene> scenes) {
        NearestScenes search = NearestScenes.of(grid, scenes, metrics, editK + 1);
        List<Scene> kept = new ArrayList<>(scenes.size());
        for (int i = 0; i < scenes.size(); i++) {
            Scene scene = scenes.get(i);
            int own = ObjectSetMetrics.actionClass(scene);
            int agree = 0;
            int others = 0;
            for (Neighbour neighbour : search.nearest(scene)) {
                if (neighbour.index() == i || others == editK) {
                    continue;
                }
                others++;
                agree += ObjectSetMetrics.actionClass(neighbour.scene()) == own ? 1 : 0;
            }
            if (others == 0 || 2 * agree >= others) {
                kept.add(scene);
            }
        }
        return kept;
    }

    @SuppressWarnings("unchecked")
    private Result condensed(List<Scene> scenes, int edited) {
        SceneMetric metric = metrics.get();
        EncodedMetric<Object> fast = metric instanceof EncodedMetric<?> encodedMetric
                ? (EncodedMetric<Object>) encodedMetric : null;
        Object[] forms = new Object[scenes.size()];
        int[] classes = new int[scenes.size()];
        for (int i = 0; i < forms.length; i++) {
            forms[i] = fast == null ? scenes.get(i) : fast.encode(scenes.get(i));
            classes[i] = ObjectSetMetrics.actionClass(scenes.get(i));
        }
        boolean[] kept = new boolean[forms.length];
        List<Integer> store = new ArrayList<>();
        kept[0] = true;
        store.add(0);
        int passes = 0;
        boolean added = true;
        while (added) {
            added = false;
            passes++;
            for (int i = 0; i < forms.length; i++) {
                if (kept[i]) {
                    continue;
                }
                int nearest = -1;
                double best = Double.POSITIVE_INFINITY;
                for (int s : store) {
                    double distance = fast == null ? metric.distance((Scene) forms[i], (Scene) forms[s])
                            : fast.distance(forms[i], forms[s], best);
                    if (distance < best || nearest < 0) {
                        best = distance;
                        nearest = s;
                    }
                }
                if (classes[nearest] != classes[i]) {
                    kept[i] = true;
                    store.add(i);
                    added = true;
                }
            }
        }
        List<Scene> result = new ArrayList<>(store.size());
        for (int i = 0; i < forms.length; i++) {
            if (kept[i]) {
                result.add(scenes.get(i));
            }
        }
        return new Result(result, edited, passes);
    }
}
