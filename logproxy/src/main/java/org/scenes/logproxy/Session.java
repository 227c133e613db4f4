package org.scenes.logproxy;

import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;

/**
 * One client as the forwarding thread sees it: its own socket facing the server, so the server
 * sees one address per client as it would without the proxy, and the server address to send
 * to, which follows the server's switch to a per-client port after {@code init}.
 */
final class Session {
    final int id;
    final Listener listener;
    final InetSocketAddress client;
    final DatagramChannel toServer;
    final Outbox outbox;
    SelectionKey key;
    SocketAddress serverTarget;
    long lastFromClient;
    long lastTraffic;
    /** The server has answered the client's init with anything but an error. */
    boolean admitted;
    /** The game is over ({@code time_over} heard) or the client said {@code (bye)}. */
    boolean ending;

    Session(int id, Listener listener, InetSocketAddress client, DatagramChannel toServer, long now) {
        this.id = id;
        this.listener = listener;
        this.client = client;
        this.toServer = toServer;
        this.outbox = new Outbox(toServer);
        this.serverTarget = listener.route.server();
        this.lastFromClient = now;
        this.lastTraffic = now;
    }
}
