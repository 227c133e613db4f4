package org.scenes.api;

/**
 * A command the observed player sent. Parameters are positional as in the protocol; an
 * optional parameter not sent (the direction of a plain {@code dash}) is {@code NaN}.
 */
public record Action(ActionType type, double first, double second) {

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

    public static Action dash(double power) {
        return new Action(ActionType.DASH, power, Double.NaN);
    }

    public static Action dash(double power, double direction) {
        return new Action(ActionType.DASH, power, direction);
    }

    public static Action turn(double moment) {
        return new Action(ActionType.TURN, moment, Double.NaN);
    }

    public static Action kick(double power, double direction) {
        return new Action(ActionType.KICK, power, direction);
    }

    public static Action turnNeck(double angle) {
        return new Action(ActionType.TURN_NECK, angle, Double.NaN);
    }

    public static Action catchBall(double direction) {
        return new Action(ActionType.CATCH, direction, Double.NaN);
    }

    public static Action move(double x, double y) {
        return new Action(ActionType.MOVE, x, y);
    }

    public static Action tackle(double power) {
        return new Action(ActionType.TACKLE, power, Double.NaN);
    }

    /** A tackle with rcssserver's foul flag ({@code (tackle 30 on)}). */
    public static Action tackle(double power, boolean foul) {
        return new Action(ActionType.TACKLE, power, foul ? 1 : 0);
    }

    /** Parameter by position (0 or 1). */
    public double parameter(int index) {
        return index == 0 ? first : second;
    }

    /** The protocol command, e.g. {@code (kick 80 -10)}; integral values print without a fraction. */
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

    /** "kick power=80 direction=-10" for tables. */
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
