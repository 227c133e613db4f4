package org.scenes.internal.target;

import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

/** How a player carries out the action of the scene it chose. */
public enum Replay {
    /** Sends the recorded command as it is: its angles are relative to the recorded player's body. */
    RAW,
    /**
     * Reaches what the recorded command achieved, in the field frame, from the player's own world
     * model ({@link Targets}); the recorded command where a world model is missing.
     */
    TARGET;

    /** The name in options and configuration files. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The replay of this key, or null. */
    public static Replay fromKey(String key) {
        for (Replay replay : values()) {
            if (replay.key().equals(key)) {
                return replay;
            }
        }
        return null;
    }

    /** The keys, for messages: "raw, target". */
    public static String keys() {
        return Arrays.stream(values()).map(Replay::key).collect(Collectors.joining(", "));
    }

    /**
     * @throws IllegalArgumentException naming the accepted values
     */
    public static Replay parse(String text) {
        Replay replay = fromKey(text);
        if (replay == null) {
            throw new IllegalArgumentException("unknown replay '" + text + "': use one of " + keys());
        }
        return replay;
    }
}
