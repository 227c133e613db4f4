package org.scenes.api;

/**
 * A command the observed player sent. Parameters are positional as in the protocol; an
 * optional parameter not sent (the direction of a plain {@code dash}) is {@code NaN}.
 *
 * @param type the command
 * @param first its first parameter, {@code NaN} when it has none
 * @param second its second parameter, {@code NaN} when it has none or it was not sent
 */
public record Action(ActionType type, double first, double second) {

    /**
     * Checks the type; parameters the type does not take become {@code NaN}.
     *
     * @param type the command
     * @param first its first parameter
     * @param second its second parameter
     */
    public Action {
        if (type == null) {
            throw new IllegalArgumentException("an action needs a type");
        }
        if (type.parameterCount() < 1) {
            first = Double.NaN;
        }
        if (type.parameterCount() < 2) {
            second = Double.NaN;
        }
    }

    /**
     * A dash without direction (straight ahead).
     *
     * @param power the dash power, as sent (the server takes -100 to 100)
     * @return the action
     */
    public static Action dash(double power) {
        return new Action(ActionType.DASH, power, Double.NaN);
    }

    /**
     * A dash in a direction relative to the body.
     *
     * @param power the dash power, as sent
     * @param direction degrees relative to the body, positive to the right
     * @return the action
     */
    public static Action dash(double power, double direction) {
        return new Action(ActionType.DASH, power, direction);
    }

    /**
     * A turn of the body.
     *
     * @param moment the turn moment in degrees, as sent (the server lessens it with speed)
     * @return the action
     */
    public static Action turn(double moment) {
        return new Action(ActionType.TURN, moment, Double.NaN);
    }

    /**
     * A kick of the ball.
     *
     * @param power the kick power, as sent
     * @param direction degrees relative to the body, positive to the right
     * @return the action
     */
    public static Action kick(double power, double direction) {
        return new Action(ActionType.KICK, power, direction);
    }

    /**
     * A turn of the neck (the head relative to the body).
     *
     * @param angle degrees, positive to the right
     * @return the action
     */
    public static Action turnNeck(double angle) {
        return new Action(ActionType.TURN_NECK, angle, Double.NaN);
    }

    /**
     * A goalie's catch.
     *
     * @param direction degrees relative to the body, positive to the right
     * @return the action
     */
    public static Action catchBall(double direction) {
        return new Action(ActionType.CATCH, direction, Double.NaN);
    }

    /**
     * A move to a place on the field (before kick-off or after a goal).
     *
     * @param x metres from the centre towards the opponent goal
     * @param y metres from the centre across the field, as the server counts
     * @return the action
     */
    public static Action move(double x, double y) {
        return new Action(ActionType.MOVE, x, y);
    }

    /**
     * A tackle without foul flag.
     *
     * @param power the tackle power or direction, as sent
     * @return the action
     */
    public static Action tackle(double power) {
        return new Action(ActionType.TACKLE, power, Double.NaN);
    }

    /**
     * A tackle with rcssserver's foul flag ({@code (tackle 30 on)}).
     *
     * @param power the tackle power or direction, as sent
     * @param foul whether the flag says {@code on}
     * @return the action, the flag as 1 or 0 in its second parameter
     */
    public static Action tackle(double power, boolean foul) {
        return new Action(ActionType.TACKLE, power, foul ? 1 : 0);
    }

    /**
     * Parameter by position (0 or 1).
     *
     * @param index 0 for the first, 1 for the second
     * @return the parameter, {@code NaN} when absent
     */
    public double parameter(int index) {
        return index == 0 ? first : second;
    }

    /**
     * The protocol command, e.g. {@code (kick 80 -10)}; integral values print without a fraction.
     *
     * @return the command as the server reads it
     */
    public String command() {
        StringBuilder command = new StringBuilder("(").append(type.key());
        for (int i = 0; i < type.parameterCount(); i++) {
            double value = parameter(i);
            if (Double.isNaN(value)) {
                continue;
            }
            // the server takes the foul flag as a word
            String word = type == ActionType.TACKLE && i == 1 ? (value != 0 ? "on" : "off") : formatNumber(value);
            command.append(' ').append(word);
        }
        return command.append(')').toString();
    }

    /**
     * "kick power=80 direction=-10" for tables.
     *
     * @return the type and each parameter sent, named
     */
    public String describe() {
        StringBuilder text = new StringBuilder(type.key());
        for (int i = 0; i < type.parameterCount(); i++) {
            double value = parameter(i);
            if (!Double.isNaN(value)) {
                text.append(' ').append(type.parameter(i)).append('=').append(formatNumber(value));
            }
        }
        return text.toString();
    }

    static String formatNumber(double value) {
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Double.toString(value);
    }
}
