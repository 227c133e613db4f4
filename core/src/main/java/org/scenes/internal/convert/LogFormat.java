package org.scenes.internal.convert;

import org.scenes.internal.proxylog.ProxyLogLine;

/**
 * Every log format of the project, each named once: {@link LogReader} reads all three, told apart
 * by their first line; the logging proxy writes {@link #NATIVE} or {@link #LSF}.
 */
public enum LogFormat {
    /**
     * The classic logging proxy's {@code .lsf}: one message per line, server messages and the
     * player's commands interleaved, no time and no direction.
     */
    LSF("lsf", "lsf"),
    /**
     * The project's own (native) proxy log, {@code docs/proxy-log-format.md}: first line
     * {@link ProxyLogLine#HEADER}, then {@code <seconds> <c2s|s2c> <escaped message>}; other
     * {@code #} lines are comments. {@link ProxyLogLine} is its codec.
     */
    NATIVE("native", "log"),
    /**
     * A timestamped capture of real rcssserver traffic:
     * {@code <unix time> <client->server|server->client> <client port> <message>}.
     */
    CAPTURE("capture", null);

    private final String label;
    private final String extension;

    LogFormat(String label, String extension) {
        this.label = label;
        this.extension = extension;
    }

    public String label() {
        return label;
    }

    /** The file name extension the logging proxy gives this format; null for a capture, which it does not write. */
    public String extension() {
        return extension;
    }

    /** The format of a log whose first non-blank line is {@code bytes[0, length)}; null when none fits. */
    static LogFormat detect(byte[] bytes, int length) {
        String magic = ProxyLogLine.HEADER;
        if (length >= magic.length() && startsWith(bytes, 0, length, magic)) {
            return NATIVE;
        }
        if (length > 0 && bytes[0] == '(') {
            return LSF;
        }
        int space = indexOf(bytes, 0, length, (byte) ' ');
        if (space > 0 && isDecimal(bytes, 0, space)) {
            int next = space + 1;
            if (startsWith(bytes, next, length, "client->server ") || startsWith(bytes, next, length, "server->client ")) {
                return CAPTURE;
            }
        }
        return null;
    }

    static boolean startsWith(byte[] bytes, int from, int length, String prefix) {
        if (length - from < prefix.length()) {
            return false;
        }
        for (int i = 0; i < prefix.length(); i++) {
            if (bytes[from + i] != prefix.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    static int indexOf(byte[] bytes, int from, int length, byte wanted) {
        return ProxyLogLine.indexOf(bytes, from, length, wanted);
    }

    static boolean isDecimal(byte[] bytes, int from, int to) {
        return ProxyLogLine.isDecimal(bytes, from, to);
    }
}
