package org.scenes.api;

import java.util.List;
import java.util.Map;

/**
 * Common face of every plugin provider found with {@link java.util.ServiceLoader}: a stable
 * short name users type ({@code ball-goal}, {@code vote}), a one-line description, and the
 * options it accepts. Names are lower case letters, digits and dashes.
 */
public interface NamedProvider {
    /** @return the name users type, unique among the providers of one kind */
    String name();

    /** @return one line for {@code scenes plugins} */
    String description();

    /**
     * Option name to one-line description; options not listed here are rejected.
     *
     * @return the accepted options, none by default
     */
    default Map<String, String> options() {
        return Map.of();
    }

    /**
     * The options {@code scenes tune --search random} may search, each with its values and scale;
     * each names one of {@link #options()} (the registry refuses a provider whose dimension does not).
     *
     * @return the searchable options, none by default
     */
    default List<TuneDimension> tuneDimensions() {
        return List.of();
    }
}
