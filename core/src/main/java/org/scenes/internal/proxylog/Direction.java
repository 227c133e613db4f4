package org.scenes.internal.proxylog;

/** Which way a datagram travelled between a client and the server, as proxy logs and captures record it. */
public enum Direction {
    CLIENT_TO_SERVER("c2s"),
    SERVER_TO_CLIENT("s2c");

    private final String token;

    Direction(String token) {
        this.token = token;
    }

    /** The word written in a native log line. */
    public String token() {
        return token;
    }

    /** The direction a log token names, or null for any other word. */
    public static Direction fromToken(String token) {
        for (Direction direction : values()) {
            if (direction.token.equals(token)) {
                return direction;
            }
        }
        return null;
    }
}
