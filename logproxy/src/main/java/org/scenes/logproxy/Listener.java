package org.scenes.logproxy;

import java.net.InetSocketAddress;
import java.nio.channels.DatagramChannel;
import java.util.HashMap;
import java.util.Map;

/** A client-facing port and the clients that talk to it. */
final class Listener {
    final Route route;
    final DatagramChannel channel;
    final Outbox outbox;
    final Map<InetSocketAddress, Session> sessions = new HashMap<>();

    Listener(Route route, DatagramChannel channel) {
        this.route = route;
        this.channel = channel;
        this.outbox = new Outbox(channel);
    }
}
