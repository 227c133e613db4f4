package org.scenes.internal.vision;

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
        return appendChange(new StringBuilder(16), value, decimals).toString();
    }

    /** {@link #formatChange} onto {@code text}. */
    public static StringBuilder appendChange(StringBuilder text, double value, int decimals) {
        if (Math.round(value * SCALE[decimals]) == 0 && (value < 0 || 1 / value < 0)) {
            return text.append("-0");
        }
        return append(text, value, decimals);
    }

    /**
     * The number a reader gets from {@link #append}'s text: the value rounded to {@code decimals}
     * places, 0 for what rounds to zero. A quotient of two whole numbers is the double nearest the
     * decimal, as a decimal read back is, however many trailing zeros the text leaves out.
     */
    public static double asRead(double value, int decimals) {
        long scaled = Math.round(value * SCALE[decimals]);
        return scaled == 0 ? 0 : scaled / SCALE[decimals];
    }

    /** The number a reader gets from {@link #appendChange}'s text: {@link #asRead}, but -0 where it writes {@code -0}. */
    public static double asReadChange(double value, int decimals) {
        if (Math.round(value * SCALE[decimals]) == 0 && (value < 0 || 1 / value < 0)) {
            return -0.0;
        }
        return asRead(value, decimals);
    }

    /** The value rounded to at most {@code decimals} places, without trailing zeros or {@code -0}. */
    public static String format(double value, int decimals) {
        return append(new StringBuilder(16), value, decimals).toString();
    }

    /** {@link #format} onto {@code text}, without a string of its own (sees are written by the million). */
    public static StringBuilder append(StringBuilder text, double value, int decimals) {
        long scaled = Math.round(value * SCALE[decimals]);
        if (scaled == 0) {
            return text.append('0');
        }
        if (scaled < 0) {
            text.append('-');
            scaled = -scaled;
        }
        long unit = (long) SCALE[decimals];
        text.append(scaled / unit);
        long fraction = scaled % unit;
        if (fraction != 0) {
            text.append('.');
            // the fraction's digits from the first place on, trailing zeros left out
            for (long place = unit / 10; fraction != 0; place /= 10) {
                text.append((char) ('0' + fraction / place));
                fraction %= place;
            }
        }
        return text;
    }
}
