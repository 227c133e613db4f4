package org.scenes.logproxy;

import java.net.InetSocketAddress;

/**
 * One port the proxy listens on for clients of one kind, and the server port it forwards them
 * to. A listen port of 0 picks a free port ({@link LogProxy#listenPort}).
 */
public record Route(ClientKind kind, int listenPort, InetSocketAddress server) {
    public Route {
        if (listenPort < 0 || listenPort > 65535) {
            throw new IllegalArgumentException("listen port out of range: " + listenPort);
        }
        if (server.isUnresolved()) {
            throw new IllegalArgumentException("unknown server host: " + server.getHostString());
        }
    }
}
