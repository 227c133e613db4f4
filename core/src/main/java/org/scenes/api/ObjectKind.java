package org.scenes.api;

import java.util.Locale;

/** What kind of thing the server reported in a {@code see} message. */
public enum ObjectKind {
    /** The ball ({@code b}). */
    BALL,
    /** A goal ({@code g l}, {@code g r}). */
    GOAL,
    /** A flag, a fixed landmark ({@code f c}, {@code f p r b}, ...). */
    FLAG,
    /** A field line ({@code l t}, ...). */
    LINE,
    /** A player ({@code p "Team" 3}, or with less when far). */
    PLAYER;

    private final String key = name().toLowerCase(Locale.ROOT);

    /**
     * Lower-case name used in scene files.
     *
     * @return the key, e.g. {@code flag}
     */
    public String key() {
        return key;
    }

    /**
     * The kind of a key, the inverse of {@link #key()}.
     *
     * @param key a key such as {@code ball}
     * @return the kind; an unknown key is an {@code IllegalArgumentException}
     */
    public static ObjectKind fromKey(String key) {
        for (ObjectKind kind : values()) {
            if (kind.key().equals(key)) {
                return kind;
            }
        }
        throw new IllegalArgumentException("unknown object kind '" + key + "'");
    }
}
