package org.scenes.vision;

/** Quantisation and number text as the server writes them in what players sense. */
public final class VisionNumbers {
    private static final double[] SCALE = {1, 10, 100, 1e3, 1e4, 1e5, 1e6};

    private VisionNumbers() {
    }

    /** The server's {@code Q(v, q) = rint(v / q) * q}. */
    public static double quantize(double value, double step) {
        return Math.rint(value / step) * step;
    }

    /**
     * A seen distance: quantised in the log domain with {@code step}, then to 0.1, so near objects
     * are exact to a decimetre and far ones coarser.
     */
    public static double seenDistance(double distance, double step) {
        return quantize(Math.exp(quantize(Math.log(Math.max(distance, 1e-6)), step)), 0.1);
    }

    /** An angle in degrees normalised to (-180, 180]. */
    public static double normalize(double degrees) {
        double a = degrees % 360;
        if (a > 180) {
            a -= 360;
        } else if (a <= -180) {
            a += 360;
        }
        return a;
    }

    /**
     * A distance or direction change: like {@link #format}, but a negative value that rounds to
     * zero, and negative zero itself, print as {@code -0}, as the server's C++ output does.
     */
    public static String formatChange(double value, int decimals) {
        if (Math.round(value * SCALE[decimals]) == 0 && (value < 0 || 1 / value < 0)) {
            return "-0";
        }
        return format(value, decimals);
    }

    /** The value rounded to at most {@code decimals} places, without trailing zeros or {@code -0}. */
    public static String format(double value, int decimals) {
        long scaled = Math.round(value * SCALE[decimals]);
        if (scaled == 0) {
            return "0";
        }
        StringBuilder text = new StringBuilder(16);
        if (scaled < 0) {
            text.append('-');
            scaled = -scaled;
        }
        long whole = scaled / (long) SCALE[decimals];
        long fraction = scaled % (long) SCALE[decimals];
        text.append(whole);
        if (fraction != 0) {
            String digits = Long.toString(fraction);
            text.append('.');
            for (int i = digits.length(); i < decimals; i++) {
                text.append('0');
            }
            int last = digits.length();
            while (digits.charAt(last - 1) == '0') {
                last--;
            }
            text.append(digits, 0, last);
        }
        return text.toString();
    }
}
