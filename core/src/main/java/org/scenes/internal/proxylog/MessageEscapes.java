package org.scenes.internal.proxylog;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Turns any datagram into one line of UTF-8 text and back, as the native proxy log format
 * requires: {@code \\} backslash, {@code \n}, {@code \r}, {@code \t}, {@code \0} NUL, and
 * {@code \xHH} for every other control byte (0x01-0x1F, 0x7F) and for every byte that is not
 * part of a well-formed UTF-8 sequence. Everything else is copied, so ordinary protocol
 * messages read the same escaped and raw. {@link #unescape} is the exact inverse of
 * {@link #escape}: {@code unescape(escape(b))} equals {@code b} for every byte array.
 */
public final class MessageEscapes {
    private static final char[] HEX = "0123456789ABCDEF".toCharArray();

    private MessageEscapes() {
    }

    public static String escape(byte[] bytes) {
        return escape(bytes, 0, bytes.length);
    }

    /** Escapes {@code length} bytes from {@code offset}. */
    public static String escape(byte[] bytes, int offset, int length) {
        byte[] out = new byte[maxEscapedLength(length)];
        int end = escape(bytes, offset, length, out, 0);
        return new String(out, 0, end, StandardCharsets.UTF_8);
    }

    /** Appends the escaped form of the bytes to {@code out}. */
    public static void appendEscaped(StringBuilder out, byte[] bytes, int offset, int length) {
        out.append(escape(bytes, offset, length));
    }

    /** Room {@link #escape(byte[], int, int, byte[], int)} may need for {@code length} bytes. */
    public static int maxEscapedLength(int length) {
        return 4 * length;
    }

    /**
     * Writes the escaped form (UTF-8) of {@code length} bytes from {@code offset} into
     * {@code target} at {@code targetOffset}, which needs {@link #maxEscapedLength} bytes of
     * room; returns the end of what was written. Allocates nothing, for the proxy's writer.
     */
    public static int escape(byte[] bytes, int offset, int length, byte[] target, int targetOffset) {
        int end = offset + length;
        int i = offset;
        int o = targetOffset;
        while (i < end) {
            int b = bytes[i] & 0xFF;
            if (b >= 0x20 && b < 0x7F) {
                if (b == '\\') {
                    target[o++] = '\\';
                }
                target[o++] = (byte) b;
                i++;
            } else if (b < 0x80) {
                o = escapeControl(target, o, b);
                i++;
            } else {
                int sequence = wellFormedLength(bytes, i, end);
                if (sequence == 0) {
                    o = escapeHex(target, o, b);
                    i++;
                } else {
                    System.arraycopy(bytes, i, target, o, sequence);
                    o += sequence;
                    i += sequence;
                }
            }
        }
        return o;
    }

    private static int escapeControl(byte[] target, int o, int b) {
        char named = switch (b) {
            case '\n' -> 'n';
            case '\r' -> 'r';
            case '\t' -> 't';
            case 0 -> '0';
            default -> 0;
        };
        if (named == 0) {
            return escapeHex(target, o, b);
        }
        target[o] = '\\';
        target[o + 1] = (byte) named;
        return o + 2;
    }

    private static int escapeHex(byte[] target, int o, int b) {
        target[o] = '\\';
        target[o + 1] = 'x';
        target[o + 2] = (byte) HEX[b >>> 4];
        target[o + 3] = (byte) HEX[b & 0xF];
        return o + 4;
    }

    /**
     * Length of the well-formed UTF-8 sequence of two to four bytes starting at {@code i}, or 0
     * when the bytes there do not form one (Unicode table 3-7: no overlong forms, no
     * surrogates, nothing above U+10FFFF).
     */
    private static int wellFormedLength(byte[] bytes, int i, int end) {
        int lead = bytes[i] & 0xFF;
        int length;
        int low = 0x80;
        int high = 0xBF;
        if (lead >= 0xC2 && lead <= 0xDF) {
            length = 2;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            if (lead == 0xE0) {
                low = 0xA0;
            } else if (lead == 0xED) {
                high = 0x9F;
            }
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            if (lead == 0xF0) {
                low = 0x90;
            } else if (lead == 0xF4) {
                high = 0x8F;
            }
        } else {
            return 0;
        }
        if (i + length > end) {
            return 0;
        }
        int second = bytes[i + 1] & 0xFF;
        if (second < low || second > high) {
            return 0;
        }
        for (int k = 2; k < length; k++) {
            int next = bytes[i + k] & 0xFF;
            if (next < 0x80 || next > 0xBF) {
                return 0;
            }
        }
        return length;
    }

    /**
     * The bytes an escaped message stands for.
     *
     * @throws IllegalArgumentException on a backslash not followed by one of the escapes
     *     above, naming the column (1-based)
     */
    public static byte[] unescape(CharSequence escaped) {
        byte[] bytes = escaped.toString().getBytes(StandardCharsets.UTF_8);
        byte[] target = new byte[bytes.length];
        int length = unescape(bytes, 0, bytes.length, target);
        return Arrays.copyOf(target, length);
    }

    /**
     * Unescapes {@code source[from, to)} into {@code target} (which needs {@code to - from} bytes)
     * and returns the number of bytes written. Escapes are ASCII, so working on the UTF-8
     * bytes of a line is the same as working on its characters, without decoding it.
     *
     * @throws IllegalArgumentException on a bad escape, naming its column counted from {@code from} (1-based)
     */
    public static int unescape(byte[] source, int from, int to, byte[] target) {
        int out = 0;
        for (int i = from; i < to; i++) {
            byte c = source[i];
            if (c != '\\') {
                target[out++] = c;
                continue;
            }
            if (i + 1 >= to) {
                throw new IllegalArgumentException("column " + (i - from + 1) + ": backslash at end of message");
            }
            byte kind = source[++i];
            switch (kind) {
                case '\\' -> target[out++] = '\\';
                case 'n' -> target[out++] = '\n';
                case 'r' -> target[out++] = '\r';
                case 't' -> target[out++] = '\t';
                case '0' -> target[out++] = 0;
                case 'x' -> {
                    int value = i + 2 < to ? hexByte((char) source[i + 1], (char) source[i + 2]) : -1;
                    if (value < 0) {
                        throw new IllegalArgumentException("column " + (i - from) + ": \\x needs two hex digits");
                    }
                    target[out++] = (byte) value;
                    i += 2;
                }
                default -> throw new IllegalArgumentException(
                        "column " + (i - from) + ": unknown escape \\" + (char) kind);
            }
        }
        return out;
    }

    private static int hexByte(char high, char low) {
        int h = Character.digit(high, 16);
        int l = Character.digit(low, 16);
        return h < 0 || l < 0 ? -1 : (h << 4) | l;
    }
}
