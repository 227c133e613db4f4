package org.scenes.proxylog;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

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
        StringBuilder out = new StringBuilder(length + 16);
        appendEscaped(out, bytes, offset, length);
        return out.toString();
    }

    /** Appends the escaped form of the bytes to {@code out}, avoiding an intermediate string. */
    public static void appendEscaped(StringBuilder out, byte[] bytes, int offset, int length) {
        int end = offset + length;
        int i = offset;
        while (i < end) {
            int b = bytes[i] & 0xFF;
            if (b >= 0x20 && b < 0x7F) {
                if (b == '\\') {
                    out.append("\\\\");
                } else {
                    out.append((char) b);
                }
                i++;
            } else if (b < 0x80) {
                appendControl(out, b);
                i++;
            } else {
                int sequence = wellFormedLength(bytes, i, end);
                if (sequence == 0) {
                    appendHex(out, b);
                    i++;
                } else {
                    out.append(new String(bytes, i, sequence, StandardCharsets.UTF_8));
                    i += sequence;
                }
            }
        }
    }

    private static void appendControl(StringBuilder out, int b) {
        switch (b) {
            case '\n' -> out.append("\\n");
            case '\r' -> out.append("\\r");
            case '\t' -> out.append("\\t");
            case 0 -> out.append("\\0");
            default -> appendHex(out, b);
        }
    }

    private static void appendHex(StringBuilder out, int b) {
        out.append("\\x").append(HEX[b >>> 4]).append(HEX[b & 0xF]);
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
        ByteArrayOutputStream out = new ByteArrayOutputStream(escaped.length());
        int length = escaped.length();
        int runStart = 0;
        int i = 0;
        while (i < length) {
            char c = escaped.charAt(i);
            if (c != '\\') {
                i++;
                continue;
            }
            writeUtf8(out, escaped, runStart, i);
            if (i + 1 >= length) {
                throw new IllegalArgumentException("column " + (i + 1) + ": backslash at end of message");
            }
            char kind = escaped.charAt(i + 1);
            switch (kind) {
                case '\\' -> out.write('\\');
                case 'n' -> out.write('\n');
                case 'r' -> out.write('\r');
                case 't' -> out.write('\t');
                case '0' -> out.write(0);
                case 'x' -> {
                    int value = i + 3 < length ? hexByte(escaped.charAt(i + 2), escaped.charAt(i + 3)) : -1;
                    if (value < 0) {
                        throw new IllegalArgumentException("column " + (i + 1) + ": \\x needs two hex digits");
                    }
                    out.write(value);
                    i += 2;
                }
                default -> throw new IllegalArgumentException(
                        "column " + (i + 1) + ": unknown escape \\" + kind);
            }
            i += 2;
            runStart = i;
        }
        writeUtf8(out, escaped, runStart, length);
        return out.toByteArray();
    }

    private static void writeUtf8(ByteArrayOutputStream out, CharSequence text, int from, int to) {
        if (from < to) {
            out.writeBytes(text.subSequence(from, to).toString().getBytes(StandardCharsets.UTF_8));
        }
    }

    private static int hexByte(char high, char low) {
        int h = Character.digit(high, 16);
        int l = Character.digit(low, 16);
        return h < 0 || l < 0 ? -1 : (h << 4) | l;
    }
}
