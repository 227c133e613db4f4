package org.scenes.convert;

/**
 * The log formats {@link LogReader} understands, told apart by their first line.
 */
public enum LogFormat {
    /**
     * The classic logging proxy's {@code .lsf}: one message per line, server messages and the
     * player's commands interleaved, no time and no direction.
     */
    LSF("lsf"),
    /**
     * The project's own proxy log: first line {@code #scenes-proxy-log 1}, then
     * {@code <seconds> <c2s|s2c> <escaped message>}; other {@code #} lines are comments.
     */
    PROXY("proxy"),
    /**
     * A timestamped capture of real rcssserver traffic:
     * {@code <unix time> <client->server|server->client> <client port> <message>}.
     */
    CAPTURE("capture");

    static final String PROXY_MAGIC = "#scenes-proxy-log 1";

    private final String label;

    LogFormat(String label) {
        this.label = label;
    }

    public String label() {
        return label;
    }

    /** The format of a log whose first non-blank line is {@code bytes[0, length)}; null when none fits. */
    static LogFormat detect(byte[] bytes, int length) {
        String magic = PROXY_MAGIC;
        if (length >= magic.length() && startsWith(bytes, 0, length, magic)) {
            return PROXY;
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
        for (int i = from; i < length; i++) {
            if (bytes[i] == wanted) {
                return i;
            }
        }
        return -1;
    }

    static boolean isDecimal(byte[] bytes, int from, int to) {
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
}
