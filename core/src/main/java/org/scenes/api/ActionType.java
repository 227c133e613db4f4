package org.scenes.api;

import java.util.Locale;

/**
 * The player commands a scene can record, in the order the thesis lists action weights
 * (none, dash, kick, turn_neck, turn, catch, move), with tackle appended.
 * {@code turn_neck} changes only what the player sees next, so it is never primary. A tackle's
 * {@code foul} is 1 for {@code on}, 0 for {@code off}, absent when not sent.
 */
public enum ActionType {
    NONE(false),
    DASH(true, "power", "direction"),
    KICK(true, "power", "direction"),
    TURN_NECK(false, "angle"),
    TURN(true, "moment"),
    CATCH(true, "direction"),
    MOVE(true, "x", "y"),
    TACKLE(true, "power", "foul");

    private final boolean worldChanging;
    private final String[] parameters;

    ActionType(boolean worldChanging, String... parameters) {
        this.worldChanging = worldChanging;
        this.parameters = parameters;
    }

    /** Whether the server executes at most one of these per cycle (it changes the world). */
    public boolean worldChanging() {
        return worldChanging;
    }

    /** Names of the parameters, in command order. */
    public String parameter(int index) {
        return parameters[index];
    }

    public int parameterCount() {
        return parameters.length;
    }

    /** The protocol's command name, also used in scene files: {@code dash}, {@code turn_neck}. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    public static ActionType fromKey(String key) {
        for (ActionType type : values()) {
            if (type.key().equals(key)) {
                return type;
            }
        }
        throw new IllegalArgumentException("unknown action type '" + key + "'");
    }
}
