package org.scenes.internal.gamelog;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

/** Numbers as the server writes them into its logs: C++ stream output, six significant digits. */
final class LogNumbers {
    private static final MathContext SIX_DIGITS = new MathContext(6, RoundingMode.HALF_EVEN);

    private LogNumbers() {
    }

    /** The server's {@code Quantize(v, q) = rint(v / q) * q}. */
    static double quantize(double value, double step) {
        return Math.rint(value / step) * step;
    }

    /**
     * The value as a default-formatted C++ stream prints it ({@code %g} with precision 6):
     * six significant digits, no trailing zeros, exponent form below 1e-4 and from 1e6, and
     * {@code -0} for negative zero.
     */
    static String format(double value) {
        if (Double.isNaN(value)) {
            return "nan";
        }
        if (Double.isInfinite(value)) {
            return value > 0 ? "inf" : "-inf";
        }
        if (value == 0) {
            return 1 / value < 0 ? "-0" : "0";
        }
        BigDecimal rounded = new BigDecimal(value).round(SIX_DIGITS);
        int exponent = rounded.precision() - rounded.scale() - 1;
        if (exponent < -4 || exponent >= 6) {
            BigDecimal mantissa = rounded.movePointLeft(exponent).stripTrailingZeros();
            String sign = exponent < 0 ? "-" : "+";
            int magnitude = Math.abs(exponent);
            return mantissa.toPlainString() + "e" + sign + (magnitude < 10 ? "0" : "") + magnitude;
        }
        return rounded.stripTrailingZeros().toPlainString();
    }
}
