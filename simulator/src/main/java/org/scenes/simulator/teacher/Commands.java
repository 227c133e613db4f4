package org.scenes.simulator.teacher;

import java.util.Locale;

/** Command text as a Java client writes it: {@code (dash 603.0)}, {@code (kick 100.0 -12.0)}. */
final class Commands {
    private Commands() {
    }

    static String dash(double power) {
        return "(dash " + number(power) + ")";
    }

    static String turn(double moment) {
        return "(turn " + number(moment) + ")";
    }

    static String kick(double power, double direction) {
        return "(kick " + number(power) + " " + number(direction) + ")";
    }

    static String move(double x, double y) {
        return "(move " + number(x) + " " + number(y) + ")";
    }

    /** One decimal at most, always with a decimal point, never in exponent form. */
    private static String number(double value) {
        double rounded = Math.rint(value * 10) / 10;
        if (rounded == 0) {
            return "0.0";
        }
        // Cheap forms first: synthetic scene generation writes a million commands.
        if (Math.abs(rounded) < 1e7) {
            return rounded == Math.rint(rounded) ? (long) rounded + ".0" : Double.toString(rounded);
        }
        return String.format(Locale.ROOT, rounded == Math.rint(rounded) ? "%.1f" : "%s", rounded);
    }
}
