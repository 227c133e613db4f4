package org.scenes.internal.proxylog;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * One message line of a native proxy log: {@code <seconds> <c2s|s2c> <escaped message>}.
 * The file starts with {@link #HEADER}; other lines starting with {@code #} are comments.
 *
 * @param micros monotonic time since the proxy started, in microseconds
 * @param message the datagram's bytes without trailing NUL padding
 */
public record ProxyLogLine(long micros, Direction direction, byte[] message) {
    /** The exact first line of every native proxy log; readers detect the format by it. */
    public static final String HEADER = "#scenes-proxy-log 1";

    public ProxyLogLine {
        message = message.clone();
    }

    @Override
    public byte[] message() {
        return message.clone();
    }

    /** The message as text; bytes that are not UTF-8 become replacement characters. */
    public String text() {
        return new String(message, StandardCharsets.UTF_8);
    }

    /** True for comment and header lines, which carry no message. */
    public static boolean isComment(String line) {
        return line.startsWith("#");
    }

    /**
     * Parses a message line.
     *
     * @throws IllegalArgumentException naming the column when the line is malformed
     */
    public static ProxyLogLine parse(String line) {
        int firstSpace = line.indexOf(' ');
        int secondSpace = firstSpace < 0 ? -1 : line.indexOf(' ', firstSpace + 1);
        if (firstSpace < 0) {
            throw new IllegalArgumentException("column 1: expected '<seconds> <c2s|s2c> <message>'");
        }
        long micros = parseMicros(line, firstSpace);
        String token = secondSpace < 0 ? line.substring(firstSpace + 1) : line.substring(firstSpace + 1, secondSpace);
        Direction direction = Direction.fromToken(token);
        if (direction == null) {
            throw new IllegalArgumentException("column " + (firstSpace + 2) + ": expected c2s or s2c, found '" + token + "'");
        }
        byte[] message;
        if (secondSpace < 0) {
            message = new byte[0];
        } else {
            try {
                message = MessageEscapes.unescape(line.substring(secondSpace + 1));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(shift(e.getMessage(), secondSpace + 1), e);
            }
        }
        return new ProxyLogLine(micros, direction, message);
    }

    /**
     * Where a message line's parts are, read from its bytes by {@link #frame}.
     *
     * @param seconds the time the line states
     * @param direction which way the datagram went; null when the frame is broken
     * @param messageStart the index of the escaped message's first byte, the line's length for an empty datagram
     * @param problem why the frame is broken, or null when it is fine
     */
    public record Frame(double seconds, Direction direction, int messageStart, String problem) {
        static Frame broken(String problem) {
            return new Frame(Double.NaN, null, -1, problem);
        }
    }

    /**
     * Reads the frame of a message line ({@code <seconds> <c2s|s2c> }) from its bytes, as a log
     * reader does for every line: leniently, any decimal seconds; the message is left escaped.
     * Comment lines ({@code #}) are the caller's to skip.
     */
    public static Frame frame(byte[] line, int length) {
        int firstSpace = indexOf(line, 0, length, (byte) ' ');
        int secondSpace = firstSpace < 0 ? -1 : indexOf(line, firstSpace + 1, length, (byte) ' ');
        int directionEnd = secondSpace < 0 ? length : secondSpace;
        if (firstSpace <= 0 || !isDecimal(line, 0, firstSpace)) {
            return Frame.broken("expected '<seconds> <c2s|s2c> <message>'");
        }
        Direction direction = isToken(line, firstSpace + 1, directionEnd, Direction.CLIENT_TO_SERVER)
                ? Direction.CLIENT_TO_SERVER
                : isToken(line, firstSpace + 1, directionEnd, Direction.SERVER_TO_CLIENT) ? Direction.SERVER_TO_CLIENT : null;
        if (direction == null) {
            return Frame.broken("direction must be c2s or s2c");
        }
        return new Frame(decimal(line, 0, firstSpace), direction, secondSpace < 0 ? length : secondSpace + 1, null);
    }

    private static boolean isToken(byte[] bytes, int from, int to, Direction direction) {
        String token = direction.token();
        if (to - from != token.length()) {
            return false;
        }
        for (int i = 0; i < token.length(); i++) {
            if (bytes[from + i] != token.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    /** The index of the first {@code wanted} byte in {@code [from, to)}, or -1. */
    public static int indexOf(byte[] bytes, int from, int to, byte wanted) {
        for (int i = from; i < to; i++) {
            if (bytes[i] == wanted) {
                return i;
            }
        }
        return -1;
    }

    /** True when {@code [from, to)} holds digits and dots only, at least one digit. */
    public static boolean isDecimal(byte[] bytes, int from, int to) {
        boolean digit = false;
        for (int i = from; i < to; i++) {
            byte c = bytes[i];
            if (c >= '0' && c <= '9') {
                digit = true;
            } else if (c != '.') {
                return false;
            }
        }
        return digit;
    }

    /** The value of a decimal that {@link #isDecimal} accepted. */
    public static double decimal(byte[] bytes, int from, int to) {
        double value = 0;
        double scale = 0;
        for (int i = from; i < to; i++) {
            byte c = bytes[i];
            if (c == '.') {
                scale = 1;
            } else {
                value = value * 10 + (c - '0');
                scale *= 10;
            }
        }
        return scale > 0 ? value / scale : value;
    }

    private static long parseMicros(String line, int end) {
        int dot = line.indexOf('.');
        if (dot <= 0 || dot >= end || end - dot - 1 != 6) {
            throw new IllegalArgumentException("column 1: expected seconds with 6 fraction digits, found '"
                    + line.substring(0, end) + "'");
        }
        try {
            long seconds = Long.parseLong(line.substring(0, dot));
            long fraction = Long.parseLong(line.substring(dot + 1, end));
            if (seconds < 0 || fraction < 0) {
                throw new NumberFormatException();
            }
            return seconds * 1_000_000L + fraction;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("column 1: bad seconds '" + line.substring(0, end) + "'", e);
        }
    }

    private static String shift(String message, int columns) {
        if (message != null && message.startsWith("column ")) {
            int colon = message.indexOf(':');
            try {
                int column = Integer.parseInt(message.substring(7, colon));
                return "column " + (column + columns) + message.substring(colon);
            } catch (RuntimeException ignored) {
                // fall through with the message unchanged
            }
        }
        return message;
    }

    /** The line as the proxy writes it, without the line break. */
    public String format() {
        StringBuilder out = new StringBuilder(message.length + 24);
        appendSeconds(out, micros);
        out.append(' ').append(direction.token()).append(' ');
        MessageEscapes.appendEscaped(out, message, 0, message.length);
        return out.toString();
    }

    /**
     * Writes one message line as {@link #format()} does, without the line break and without
     * allocating: the form the logging proxy's writer thread gives every datagram.
     *
     * @param target room for the line: 28 bytes plus {@link MessageEscapes#maxEscapedLength} of the message
     * @return the end of the line in {@code target}
     */
    public static int write(long micros, Direction direction, byte[] message, int offset, int length, byte[] target) {
        int end = writeSeconds(target, micros);
        target[end++] = ' ';
        String token = direction.token();
        for (int i = 0; i < token.length(); i++) {
            target[end++] = (byte) token.charAt(i);
        }
        target[end++] = ' ';
        return MessageEscapes.escape(message, offset, length, target, end);
    }

    /** Seconds with six fraction digits, written from the start of {@code target}; returns the end. */
    static int writeSeconds(byte[] target, long micros) {
        long seconds = micros / 1_000_000L;
        int digits = 1;
        for (long rest = seconds / 10; rest > 0; rest /= 10) {
            digits++;
        }
        for (int i = digits - 1; i >= 0; i--) {
            target[i] = (byte) ('0' + seconds % 10);
            seconds /= 10;
        }
        int end = digits;
        target[end++] = '.';
        long fraction = micros % 1_000_000L;
        for (int i = 5; i >= 0; i--) {
            target[end + i] = (byte) ('0' + fraction % 10);
            fraction /= 10;
        }
        return end + 6;
    }

    /** Appends microseconds as seconds with exactly 6 fraction digits. */
    public static void appendSeconds(StringBuilder out, long micros) {
        out.append(micros / 1_000_000L).append('.');
        String fraction = Long.toString(micros % 1_000_000L);
        for (int pad = fraction.length(); pad < 6; pad++) {
            out.append('0');
        }
        out.append(fraction);
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof ProxyLogLine line && line.micros == micros && line.direction == direction
                && Arrays.equals(line.message, message);
    }

    @Override
    public int hashCode() {
        return Long.hashCode(micros) * 31 + direction.hashCode() * 17 + Arrays.hashCode(message);
    }

    @Override
    public String toString() {
        return format();
    }
}
