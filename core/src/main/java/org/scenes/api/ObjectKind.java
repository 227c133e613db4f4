package org.scenes.api;

/** What kind of thing the server reported in a {@code see} message. */
public enum ObjectKind {
    BALL, GOAL, FLAG, LINE, PLAYER;

    private final String key = name().toLowerCase(java.util.Locale.ROOT);

    /** Lower-case name used in scene files. */
    public String key() {
        return key;
    }

    public static ObjectKind fromKey(String key) {
        for (ObjectKind kind : values()) {
            if (kind.key().equals(key)) {
                return kind;
            }
        }
        throw new IllegalArgumentException("unknown object kind '" + key + "'");
    }
}
