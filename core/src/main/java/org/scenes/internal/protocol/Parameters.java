package org.scenes.internal.protocol;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * {@code server_param}, {@code player_param} or {@code player_type}. Version 8 and later send named
 * pairs (kept in {@link #named()} in order, string values without quotes); version 7 sends the
 * values by position only ({@link #positional()}).
 */
public record Parameters(String head, Map<String, String> named, List<String> positional) implements Message {
    public Parameters {
        named = Collections.unmodifiableMap(new LinkedHashMap<>(named));
        positional = List.copyOf(positional);
    }

    /** A named parameter as a number, {@code NaN} when absent or not numeric. */
    public double number(String name) {
        return number(named, name, Double.NaN);
    }

    /**
     * A parameter of a name-to-value map (a {@link #named()}, or several merged) as a number,
     * {@code fallback} when the map or the name is absent or the value not numeric.
     */
    public static double number(Map<String, String> named, String name, double fallback) {
        String value = named == null ? null : named.get(name);
        if (value == null) {
            return fallback;
        }
        try {
            return Double.parseDouble(value);
        } catch (NumberFormatException e) {
            return fallback;
        }
    }
}
