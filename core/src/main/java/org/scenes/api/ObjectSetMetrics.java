package org.scenes.api;

import java.util.ArrayList;
import java.util.List;
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
     * The dimensions {@code scenes tune} may search for an object-set metric that compares positions
     * ({@code continuous}, {@code projection}): the polar space's distance and direction weights, the
     * side of the heading, the distance rings, the unmatched penalty and its scale, and for a
     * projecting metric the cycles projected. The values are the random search's (docs/validation.md).
     *
     * @param projection true for a projecting metric's {@code cycles}
     * @return the dimensions, in the order the search draws them
     */
    public static List<TuneDimension> tuneDimensions(boolean projection) {
        List<TuneDimension> dimensions = new ArrayList<>(List.of(
                TuneDimension.log("distance-weight", 1, 3, 10, 30, 100),
                TuneDimension.log("direction-weight", 0.3, 1, 3, 10, 30, 100),
                TuneDimension.log("side-weight", 30, 100, 300, 1000),
                // 1000 twice: drawn twice as often; 0: no rings
                TuneDimension.log("row-weight", 0, 10, 100, 1000, 1000, 3000),
                TuneDimension.log("penalty", 10, 100, 1000, 20000, 20000),
                TuneDimension.log("penalty-scale", 10, 100, 10000)));
        if (projection) {
            dimensions.add(TuneDimension.linear("cycles", -1, 1, 2));
        }
        return dimensions;
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
