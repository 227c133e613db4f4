package org.scenes.api;

import java.util.Locale;

/**
 * How a seen object relates to the observer. Goals are {@link #OWN} or {@link #OPPONENT};
 * players are {@link #TEAMMATE}, {@link #OPPONENT} or {@link #UNKNOWN} (team not readable);
 * ball, flags and lines have {@link #NONE}. A goal is {@link #UNKNOWN} only when the
 * observer's side was never learned.
 */
public enum Relation {
    NONE, OWN, OPPONENT, TEAMMATE, UNKNOWN;

    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    public static Relation fromKey(String key) {
        for (Relation relation : values()) {
            if (relation.key().equals(key)) {
                return relation;
            }
        }
        throw new IllegalArgumentException("unknown relation '" + key + "'");
    }
}
