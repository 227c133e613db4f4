package org.scenes.simulator.server;

import java.net.SocketAddress;
import java.nio.channels.DatagramChannel;
import org.scenes.simulator.Seat;

/** A connected client: the server's socket dedicated to it, its address, its seat. */
final class Remote {
    final DatagramChannel channel;
    final SocketAddress address;
    Seat seat;
    /** Synchronous mode: {@code (done)} received since the last {@code (think)}. */
    boolean done;

    Remote(DatagramChannel channel, SocketAddress address) {
        this.channel = channel;
        this.address = address;
    }
}
