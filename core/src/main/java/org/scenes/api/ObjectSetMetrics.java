package org.scenes.api;

import java.util.Map;
import org.scenes.internal.match.ObjectSetMetric;

/**
 * The object-set metric as plugins build it: the objects of each class are paired between the two
 * scenes, a pair costs its distance, an object left without a partner costs a penalty. The
 * {@code continuous}, {@code cell} and {@code projection} metrics are this one engine with other
 * defaults; a plugin that wants a variant starts from here rather than from the engine itself,
 * which may change.
 */
public final class ObjectSetMetrics {
    private ObjectSetMetrics() {
    }

    /**
     * Options every object-set metric accepts, name to one-line description, for a provider's
     * {@code options()}.
     *
     * @param projection true for the {@code cycles} option of a projecting metric, false for the
     *     {@code space} option
     * @return option name to description, in a stable order
     */
    public static Map<String, String> options(boolean projection) {
        return ObjectSetMetric.options(projection);
    }

    /**
     * Objects placed at x = r cos(dir), y = r sin(dir) (or compared in polar form with the option
     * {@code space=polar}).
     *
     * @param config the plugin's configuration and options
     * @param defaultCycles cycles objects are moved forward by their changes when the options do
     *     not say ({@code cycles}); 0 for none
     * @return a new metric, for one thread
     */
    public static SceneMetric cartesian(PluginConfig config, double defaultCycles) {
        return ObjectSetMetric.create(config, ObjectSetMetric.Space.CARTESIAN, defaultCycles);
    }

    /**
     * Objects placed at their grid cell (column, row); pairs cost the distance between cells.
     *
     * @param config the plugin's configuration and options
     * @return a new metric, for one thread
     */
    public static SceneMetric cells(PluginConfig config) {
        return ObjectSetMetric.create(config, ObjectSetMetric.Space.CELL, 0);
    }

    /**
     * A scene's action as the metrics compare it: the primary type, with turns split by the sign of
     * the moment (left, straight, right), since the direction of a turn is what an agent repeats.
     *
     * @param scene any scene
     * @return a small number, equal for scenes whose actions count as the same
     */
    public static int actionClass(Scene scene) {
        return ObjectSetMetric.actionClass(scene);
    }
}
