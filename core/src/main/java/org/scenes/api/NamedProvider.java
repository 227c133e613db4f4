package org.scenes.api;

import java.util.Map;

/**
 * Common face of every plugin provider found with {@link java.util.ServiceLoader}: a stable
 * short name users type ({@code ball-goal}, {@code vote}), a one-line description, and the
 * options it accepts. Names are lower case letters, digits and dashes.
 */
public interface NamedProvider {
    String name();

    String description();

    /** Option name to one-line description; options not listed here are rejected. */
    default Map<String, String> options() {
        return Map.of();
    }
}
