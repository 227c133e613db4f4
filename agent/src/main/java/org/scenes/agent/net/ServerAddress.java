package org.scenes.agent.net;

import java.net.InetSocketAddress;

/** Where a soccer server takes player inits: {@code HOST:PORT}, e.g. {@code 127.0.0.1:6000}. */
public record ServerAddress(String host, int port) {
    public ServerAddress {
        if (host == null || host.isBlank()) {
            throw new IllegalArgumentException("the server host is empty");
        }
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("the server port must be 1 to 65535, not " + port);
        }
    }

    /** Parses {@code HOST:PORT}; a message naming what is wrong otherwise. */
    public static ServerAddress parse(String text) {
        int colon = text.lastIndexOf(':');
        if (colon <= 0 || colon == text.length() - 1) {
            throw new IllegalArgumentException("expected HOST:PORT, e.g. 127.0.0.1:6000, not '" + text + "'");
        }
        int port;
        try {
            port = Integer.parseInt(text.substring(colon + 1));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("the port of '" + text + "' is not a number");
        }
        return new ServerAddress(text.substring(0, colon), port);
    }

    InetSocketAddress socketAddress() {
        return new InetSocketAddress(host, port);
    }

    @Override
    public String toString() {
        return host + ":" + port;
    }
}
