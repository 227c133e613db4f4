package org.scenes.api;

import java.util.Arrays;
import java.util.Collections;

/** Parsing of weight lists, positional ({@code 1/0/1}, {@code {1,0,1}}) or named ({@code ball=1}). */
final class Weights {
    private Weights() {
    }

    /** Named form: classes not named weigh 0. */
    static double[] parse(String text, String[] names, String what) {
        return parseWithDefault(text, names, what, 0, names.length);
    }

    /**
     * @param unnamed weight of classes the named form leaves out
     * @param minimumPositional fewest values the positional form accepts; later ones keep {@code unnamed}
     */
    static double[] parseWithDefault(String text, String[] names, String what, double unnamed, int minimumPositional) {
        String trimmed = text == null ? "" : text.trim();
        if (trimmed.startsWith("{") && trimmed.endsWith("}")) {
            trimmed = trimmed.substring(1, trimmed.length() - 1).trim();
        }
        if (trimmed.isEmpty()) {
            throw new IllegalArgumentException(what + " are empty; expected e.g. "
                    + String.join("/", Collections.nCopies(names.length, "1")) + " or " + names[1] + "=1");
        }
        double[] weights = new double[names.length];
        if (trimmed.contains("=")) {
            Arrays.fill(weights, unnamed);
            for (String part : trimmed.split("[,/]")) {
                String[] pair = part.split("=", 2);
                if (pair.length != 2) {
                    throw new IllegalArgumentException(what + ": '" + part.trim() + "' is not name=weight");
                }
                int index = indexOf(names, pair[0].trim(), what);
                weights[index] = number(pair[1].trim(), what);
            }
            return weights;
        }
        String[] parts = trimmed.split("\\s*[,/]\\s*");
        if (parts.length < minimumPositional || parts.length > names.length) {
            throw new IllegalArgumentException(what + " need " + (minimumPositional == names.length ? "" : minimumPositional + " to ")
                    + names.length + " values (" + String.join("/", names) + "), not " + parts.length);
        }
        Arrays.fill(weights, unnamed);
        for (int i = 0; i < parts.length; i++) {
            weights[i] = number(parts[i], what);
        }
        return weights;
    }

    private static int indexOf(String[] names, String name, String what) {
        for (int i = 0; i < names.length; i++) {
            if (names[i].equalsIgnoreCase(name)) {
                return i;
            }
        }
        throw new IllegalArgumentException(what + ": unknown class '" + name + "'; known: " + String.join(", ", names));
    }

    private static double number(String text, String what) {
        try {
            double value = Double.parseDouble(text);
            if (!(value >= 0) || Double.isInfinite(value)) {
                throw new IllegalArgumentException(what + ": weight '" + text + "' must be a finite number >= 0");
            }
            return value;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + ": '" + text + "' is not a number");
        }
    }

    static String format(double[] weights) {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < weights.length; i++) {
            if (i > 0) {
                text.append('/');
            }
            double weight = weights[i];
            text.append(weight == Math.rint(weight) ? Long.toString((long) weight) : Double.toString(weight));
        }
        return text.toString();
    }
}
