package org.scenes.internal.protocol;

import java.nio.charset.StandardCharsets;
import java.util.Locale;

/**
 * The bytes of one message and a position in them, with the token readers every part of the
 * parser shares: spaces, atoms, strings, lists, numbers parsed in place, errors with the column.
 * {@link MessageParser} extends it so that its hot loops (see, commands) read the position as
 * their own field, with no extra indirection; the readers of the other messages hold it.
 */
abstract class MessageCursor {
    private static final double[] POWERS_OF_TEN = new double[23];

    static {
        POWERS_OF_TEN[0] = 1;
        for (int i = 1; i < POWERS_OF_TEN.length; i++) {
            POWERS_OF_TEN[i] = POWERS_OF_TEN[i - 1] * 10;
        }
    }

    /** Heads, keys, team names and flag values, decoded once per distinct spelling. */
    final NameTable<String> words = new NameTable<>();
    /** The numbers of the list being read (see {@link #numbers()}). */
    final double[] numbers = new double[8];

    byte[] buf;
    /** Where columns are counted from: the datagram or line, not the message within it. */
    int origin;
    int start;
    int pos;
    int end;

    final void skipSpace() {
        while (pos < end && isSpace(buf[pos])) {
            pos++;
        }
    }

    static boolean isSpace(byte c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    }

    /**
     * Whether the quote at {@code i} opens a string: only at the start of an atom. A quote inside
     * an atom ({@code p"x(}) is an ordinary byte, as {@link #atomEnd()} reads it; the balance check
     * and the skipping must agree with it, or parentheses one skips the other counts (found by fuzzing).
     */
    final boolean startsString(int i) {
        if (i == start) {
            return true;
        }
        byte before = buf[i - 1];
        return before == '(' || before == ')' || isSpace(before);
    }

    /** End of the atom or string at {@code pos}. */
    final int atomEnd() {
        int p = pos;
        if (p < end && buf[p] == '"') {
            p++;
            while (p < end && buf[p] != '"') {
                p++;
            }
            return Math.min(p + 1, end);
        }
        while (p < end) {
            byte c = buf[p];
            if (c == '(' || c == ')' || isSpace(c)) {
                break;
            }
            p++;
        }
        return p;
    }

    /** Moves past one atom, string or balanced list. */
    final void skipElement() {
        if (buf[pos] != '(') {
            pos = Math.max(atomEnd(), pos + 1);
            return;
        }
        pos++;
        skipToClose();
        pos++;
    }

    /** Moves to the ')' closing the current list (balance was checked before). */
    final void skipToClose() {
        int depth = 0;
        while (pos < end) {
            byte c = buf[pos];
            if (c == '"' && startsString(pos)) {
                pos = atomEnd();
                continue;
            }
            if (c == '(') {
                depth++;
            } else if (c == ')') {
                if (depth == 0) {
                    return;
                }
                depth--;
            }
            pos++;
        }
    }

    /** Reads numbers until the list closes; returns how many (more than fit counts as too many). */
    final int numbers() {
        int count = 0;
        while (true) {
            skipSpace();
            if (buf[pos] == ')' || buf[pos] == '(') {
                return count;
            }
            int tokenEnd = atomEnd();
            double value = number(pos, tokenEnd);
            pos = tokenEnd;
            if (Double.isNaN(value) || count == numbers.length) {
                return -1;
            }
            numbers[count++] = value;
        }
    }

    final String word() {
        skipSpace();
        int wordStart = pos;
        pos = atomEnd();
        return NameTable.string(words, buf, wordStart, pos);
    }

    final int integer(String what) {
        skipSpace();
        int tokenEnd = atomEnd();
        double value = number(pos, tokenEnd);
        if (Double.isNaN(value) || value != Math.rint(value) || Math.abs(value) > Integer.MAX_VALUE) {
            throw error("expected " + what + " (an integer) but found '" + text(pos, tokenEnd) + "'");
        }
        pos = tokenEnd;
        return (int) value;
    }

    /** The words after the head up to the closing parenthesis. */
    final String restText() {
        return text(pos, end - 1).trim();
    }

    /**
     * Parses a decimal number in place; {@code NaN} when the token is not a number. Up to 15
     * significant digits and 22 fraction digits the result is exact (one correctly rounded
     * division); anything longer or with an exponent goes through {@link Double#parseDouble}.
     */
    final double number(int s, int e) {
        if (s >= e) {
            return Double.NaN;
        }
        int i = s;
        boolean negative = false;
        if (buf[i] == '-' || buf[i] == '+') {
            negative = buf[i] == '-';
            i++;
        }
        long mantissa = 0;
        int digits = 0;
        int fraction = 0;
        boolean dot = false;
        for (; i < e; i++) {
            byte c = buf[i];
            if (c >= '0' && c <= '9') {
                if (digits < 18) {
                    mantissa = mantissa * 10 + (c - '0');
                }
                digits++;
                if (dot) {
                    fraction++;
                }
            } else if (c == '.' && !dot) {
                dot = true;
            } else if (c == 'e' || c == 'E') {
                return slowNumber(s, e);
            } else {
                return Double.NaN;
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        if (digits >= 18 || mantissa >= (1L << 53) || fraction >= POWERS_OF_TEN.length) {
            return slowNumber(s, e);
        }
        double value = fraction == 0 ? mantissa : mantissa / POWERS_OF_TEN[fraction];
        return negative ? -value : value;
    }

    /** NaN also for what overflows to infinity (1e999): the protocol has no infinite values. */
    private double slowNumber(int s, int e) {
        try {
            double value = Double.parseDouble(text(s, e));
            return Double.isFinite(value) ? value : Double.NaN;
        } catch (NumberFormatException ex) {
            return Double.NaN;
        }
    }

    /** A token meant as a number: a digit, sign or dot first, or a spelling of infinity or NaN. */
    final boolean looksLikeNumber(int s, int e) {
        byte first = buf[s];
        if ((first >= '0' && first <= '9') || first == '-' || first == '+' || first == '.') {
            return true;
        }
        String word = text(s, e).toLowerCase(Locale.ROOT);
        return word.equals("nan") || word.startsWith("inf");
    }

    final boolean equals(int s, int e, String literal) {
        if (e - s != literal.length()) {
            return false;
        }
        for (int i = 0; i < literal.length(); i++) {
            if (buf[s + i] != literal.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    final String text(int s, int e) {
        return new String(buf, s, Math.max(0, e - s), StandardCharsets.UTF_8);
    }

    final ProtocolException error(String message) {
        return errorAt(pos, message);
    }

    final ProtocolException errorAt(int at, String message) {
        return new ProtocolException(at - origin + 1, message);
    }
}
