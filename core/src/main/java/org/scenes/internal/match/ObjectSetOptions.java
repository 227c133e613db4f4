package org.scenes.internal.match;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.Scene;
import org.scenes.internal.match.ObjectSetMetric.Matching;
import org.scenes.internal.match.ObjectSetMetric.Settings;
import org.scenes.internal.match.ObjectSetMetric.Space;

/** The options of the object-set metrics: their descriptions, and the settings a plugin config asks for. */
final class ObjectSetOptions {
    private ObjectSetOptions() {
    }

    /** Options every object-set metric accepts, with descriptions, for the providers' {@code options()}. */
    static Map<String, String> describe(boolean projection) {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("matching", "greedy (sort by distance, pair in order; default) or optimal (minimum-cost assignment)");
        options.put("log-distance", "true to compare ln(1 + distance) instead of distance (default false)");
        options.put("distance-weight", "weight of distance differences in polar space (default 1)");
        options.put("direction-weight", "weight of direction differences, per degree, in polar space (default 1)");
        options.put("row-weight", "cost per grid row (distance ring) of difference, added to the pair cost (default 0)");
        options.put("penalty", "cost of an unmatched object at the observer (default 10)");
        options.put("penalty-scale", "distance at which the unmatched penalty halves (default 10)");
        options.put("memory", "weight of the remembered previous scene (needs the memory transform; default 0)");
        options.put("memory-direction-weight", "direction-weight of the remembered previous scene, per degree, in polar space"
                + " (default: direction-weight)");
        options.put("side-weight", "cost added to a pair on different sides of the heading: left, straight ahead, right"
                + " (default 0); agents that turn until an object is dead ahead decide by its side, not by its degrees");
        options.put("ahead-width", "degrees counted as straight ahead for side-weight, centred on the heading (default 1:"
                + " the directions the server rounds to 0)");
        options.put("own-goal-weight", "the own goal's weight as a share of the goal weight (default 1); 0 for agents that"
                + " look only at the goal they attack");
        options.put("memory-row-weight", "row-weight of the remembered previous scene (default: row-weight)");
        options.put("memory-action", "cost when the remembered previous actions differ in type or turn direction (default 0)");
        options.put("nearest-players", "true to compare only the nearest player of each weighted player class"
                + " (teammates, opponents, unknown, all players), which the exact index then serves (default false)");
        options.put("memory-depth", "previous actions memory-action compares, 1 to " + Scene.MAX_MEMORY
                + " (default 1); the i-th back costs memory-action · memory-decay^(i-1)");
        options.put("memory-decay", "factor of each further action back (default 0.5)");
        options.put("index", "true (default) to search an exact index when every weighted group holds at most one object"
                + " per scene (ball, goals, nearest players); false to scan every scene");
        if (projection) {
            options.put("cycles", "cycles to project objects forward by their distance/direction change (default 1; negative: back)");
        } else {
            options.put("space", "cartesian or polar (default for continuous: cartesian)");
        }
        return options;
    }

    /** The {@code index} option: whether low-dimensional configurations search the exact index (default true). */
    static boolean indexed(PluginConfig config) {
        String index = config.option("index", "true").toLowerCase(Locale.ROOT);
        if (!index.equals("true") && !index.equals("false")) {
            throw new PluginException("option index=" + index + " must be true or false");
        }
        return index.equals("true");
    }

    /** Settings from a plugin config, with the defaults of the calling metric. */
    static Settings settings(PluginConfig config, Space defaultSpace, double defaultProjection) {
        Matching matching = switch (config.option("matching", "greedy").toLowerCase(Locale.ROOT)) {
            case "greedy" -> Matching.GREEDY;
            case "optimal" -> Matching.OPTIMAL;
            default -> throw new PluginException("option matching=" + config.option("matching", "")
                    + " is unknown; use greedy or optimal");
        };
        Space space = defaultSpace;
        if (config.options().containsKey("space")) {
            space = switch (config.option("space", "").toLowerCase(Locale.ROOT)) {
                case "cartesian" -> Space.CARTESIAN;
                case "polar" -> Space.POLAR;
                default -> throw new PluginException("option space=" + config.option("space", "")
                        + " is unknown; use cartesian or polar");
            };
        }
        return new Settings(config.objectWeights(), matching, space, flag(config, "log-distance"),
                config.doubleOption("distance-weight", 1), config.doubleOption("direction-weight", 1),
                config.doubleOption("row-weight", 0),
                config.doubleOption("penalty", 10), config.doubleOption("penalty-scale", 10),
                config.doubleOption("cycles", defaultProjection), config.doubleOption("memory", 0),
                config.doubleOption("memory-action", 0), memoryDepth(config), config.doubleOption("memory-decay", 0.5),
                flag(config, "nearest-players"),
                config.doubleOption("memory-direction-weight", config.doubleOption("direction-weight", 1)),
                config.doubleOption("side-weight", 0), config.doubleOption("ahead-width", 1),
                config.doubleOption("own-goal-weight", 1),
                config.doubleOption("memory-row-weight", config.doubleOption("row-weight", 0)));
    }

    /** A true/false option, false by default. */
    private static boolean flag(PluginConfig config, String name) {
        String value = config.option(name, "false").toLowerCase(Locale.ROOT);
        if (!value.equals("true") && !value.equals("false")) {
            throw new PluginException("option " + name + "=" + value + " must be true or false");
        }
        return value.equals("true");
    }

    private static int memoryDepth(PluginConfig config) {
        double depth = config.doubleOption("memory-depth", 1);
        if (depth != Math.rint(depth) || depth < 1 || depth > Scene.MAX_MEMORY) {
            throw new PluginException("option memory-depth must be a whole number from 1 to " + Scene.MAX_MEMORY
                    + ", not " + config.option("memory-depth", ""));
        }
        return (int) depth;
    }
}
