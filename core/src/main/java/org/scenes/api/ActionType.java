package org.scenes.api;

import java.util.Locale;

/**
 * The player commands a scene can record, in the order the thesis lists action weights
 * (none, dash, kick, turn_neck, turn, catch, move), with tackle appended.
 * {@code turn_neck} changes only what the player sees next, so it is never primary. A tackle's
 * {@code foul} is 1 for {@code on}, 0 for {@code off}, absent when not sent.
 */
public enum ActionType {
    /** No command after the see. */
    NONE(false),
    /** Accelerate: power, and direction in degrees relative to the body (optional). */
    DASH(true, "power", "direction"),
    /** Kick the ball: power, direction in degrees relative to the body. */
    KICK(true, "power", "direction"),
    /** Turn the head relative to the body: angle in degrees. */
    TURN_NECK(false, "angle"),
    /** Turn the body: moment in degrees. */
    TURN(true, "moment"),
    /** The goalie's catch: direction in degrees relative to the body. */
    CATCH(true, "direction"),
    /** Place the player on the field (before kick-off, after a goal): x and y in metres. */
    MOVE(true, "x", "y"),
    /** Tackle: power (a direction in newer servers) and the foul flag. */
    TACKLE(true, "power", "foul");

    private final boolean worldChanging;
    private final String[] parameters;
    /** Computed once: scene files ask for it per action. */
    private final String key = name().toLowerCase(Locale.ROOT);

    ActionType(boolean worldChanging, String... parameters) {
        this.worldChanging = worldChanging;
        this.parameters = parameters;
    }

    /**
     * Whether the server executes at most one of these per cycle (it changes the world).
     *
     * @return true for every type but none and turn_neck
     */
    public boolean worldChanging() {
        return worldChanging;
    }

    /**
     * Names of the parameters, in command order.
     *
     * @param index from 0, below {@link #parameterCount()}
     * @return the parameter's name, e.g. {@code power}
     */
    public String parameter(int index) {
        return parameters[index];
    }

    /**
     * How many parameters the command takes, optional ones included.
     *
     * @return the count, 0 to 2
     */
    public int parameterCount() {
        return parameters.length;
    }

    /**
     * The protocol's command name, also used in scene files: {@code dash}, {@code turn_neck}.
     *
     * @return the lower-case name
     */
    public String key() {
        return key;
    }

    /**
     * The type of a command name, the inverse of {@link #key()}.
     *
     * @param key a command name such as {@code dash}
     * @return the type; an unknown name is an {@code IllegalArgumentException}
     */
    public static ActionType fromKey(String key) {
        for (ActionType type : values()) {
            if (type.key().equals(key)) {
                return type;
            }
        }
        throw new IllegalArgumentException("unknown action type '" + key + "'");
    }
}
