package org.scenes.logproxy;

import java.io.IOException;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.util.ArrayDeque;

/**
 * Sends datagrams on one channel in order. A send the kernel cannot take right now (full
 * socket buffer) is kept and retried when the channel becomes writable, so a burst is delayed
 * rather than lost; only beyond {@link #MAX_PENDING_BYTES} is a datagram dropped.
 */
final class Outbox {
    static final int MAX_PENDING_BYTES = 8 << 20;

    private final DatagramChannel channel;
    private final ArrayDeque<Pending> pending = new ArrayDeque<>();
    private SelectionKey key;
    private long pendingBytes;

    private record Pending(ByteBuffer bytes, SocketAddress target) {
    }

    Outbox(DatagramChannel channel) {
        this.channel = channel;
    }

    void key(SelectionKey key) {
        this.key = key;
    }

    /**
     * Sends the buffer's remaining bytes to {@code target}; returns false if the datagram was
     * dropped. The buffer's position is left where it was.
     */
    boolean send(ByteBuffer buffer, SocketAddress target) throws IOException {
        if (pending.isEmpty()) {
            int position = buffer.position();
            int length = buffer.remaining();
            int sent = channel.send(buffer, target);
            buffer.position(position);
            // An empty datagram reports 0 bytes sent either way; UDP sends all or nothing.
            if (sent > 0 || length == 0) {
                return true;
            }
        }
        if (pendingBytes + buffer.remaining() > MAX_PENDING_BYTES) {
            return false;
        }
        ByteBuffer copy = ByteBuffer.allocate(buffer.remaining());
        copy.put(buffer.duplicate()).flip();
        pending.add(new Pending(copy, target));
        pendingBytes += copy.remaining();
        key.interestOps(key.interestOps() | SelectionKey.OP_WRITE);
        return true;
    }

    /** Called when the channel is writable: sends what it can, in order. */
    void flush() throws IOException {
        while (!pending.isEmpty()) {
            Pending next = pending.peek();
            int length = next.bytes().remaining();
            if (channel.send(next.bytes(), next.target()) == 0 && length > 0) {
                return;
            }
            pending.poll();
            pendingBytes -= length;
        }
        key.interestOps(key.interestOps() & ~SelectionKey.OP_WRITE);
    }

    int pendingCount() {
        return pending.size();
    }
}
