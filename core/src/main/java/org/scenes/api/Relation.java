package org.scenes.api;

import java.util.Locale;

/**
 * How a seen object relates to the observer. Goals are {@link #OWN} or {@link #OPPONENT};
 * players are {@link #TEAMMATE}, {@link #OPPONENT} or {@link #UNKNOWN} (team not readable);
 * ball, flags and lines have {@link #NONE}. A goal is {@link #UNKNOWN} only when the
 * observer's side was never learned.
 */
public enum Relation {
    /** No relation: the ball, flags and lines. */
    NONE,
    /** The observer's own goal. */
    OWN,
    /** The opponents' goal, or a player of the other team. */
    OPPONENT,
    /** A player of the observer's team. */
    TEAMMATE,
    /** A player whose team could not be read, or a goal while the observer's side is unknown. */
    UNKNOWN;

    /** Computed once: scene files and world models ask for it per object. */
    private final String key = name().toLowerCase(Locale.ROOT);

    /**
     * Lower-case name used in scene files.
     *
     * @return the key, e.g. {@code opponent}
     */
    public String key() {
        return key;
    }

    /**
     * The relation of a key, the inverse of {@link #key()}.
     *
     * @param key a key such as {@code own}
     * @return the relation; an unknown key is an {@code IllegalArgumentException}
     */
    public static Relation fromKey(String key) {
        for (Relation relation : values()) {
            if (relation.key().equals(key)) {
                return relation;
            }
        }
        throw new IllegalArgumentException("unknown relation '" + key + "'");
    }
}
