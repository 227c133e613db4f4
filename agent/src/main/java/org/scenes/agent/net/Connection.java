package org.scenes.agent.net;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.charset.StandardCharsets;

/**
 * One player's UDP socket. The first datagram goes to the server's init port; the server answers
 * from a port of its own for this client, and from then on everything goes to that port and only
 * datagrams from it are taken (others are dropped). The socket is not
 * {@code connect}ed: connecting may discard what already waits in its buffer, and the server
 * sends its parameters right after the init answer. Every datagram sent ends with a NUL, as the
 * real server expects from version 8 on.
 */
final class Connection implements AutoCloseable {
    /** Larger than any message the server sends (its buffer is 8 KB). */
    private static final int MAX_DATAGRAM = 1 << 16;
    private static final int MAX_DROPPED_PER_POLL = 256;

    private final DatagramChannel channel;
    private final Selector selector;
    private final ByteBuffer in = ByteBuffer.allocate(MAX_DATAGRAM);
    private final InetSocketAddress initPort;
    private InetSocketAddress clientPort;

    /** One message received: its bytes without trailing NULs, when it arrived. */
    record Datagram(byte[] bytes, long receivedNanos) {
        String text() {
            return new String(bytes, StandardCharsets.UTF_8);
        }

        /** The integer after the head word ({@code (sense_body 42 ...)}: 42), -1 when there is none. */
        int time() {
            int i = 0;
            while (i < bytes.length && bytes[i] != ' ') {
                i++;
            }
            int value = 0;
            int digits = 0;
            for (i++; i < bytes.length && bytes[i] >= '0' && bytes[i] <= '9' && digits < 9; i++, digits++) {
                value = value * 10 + (bytes[i] - '0');
            }
            return digits == 0 ? -1 : value;
        }

        boolean startsWith(String head) {
            if (bytes.length < head.length()) {
                return false;
            }
            for (int i = 0; i < head.length(); i++) {
                if (bytes[i] != head.charAt(i)) {
                    return false;
                }
            }
            return true;
        }
    }

    Connection(ServerAddress server) throws IOException {
        initPort = server.socketAddress();
        if (initPort.isUnresolved()) {
            throw new IOException("unknown host '" + server.host() + "'");
        }
        channel = DatagramChannel.open();
        try {
            channel.bind(null);
            channel.configureBlocking(false);
            selector = Selector.open();
            channel.register(selector, SelectionKey.OP_READ);
        } catch (IOException e) {
            channel.close();
            throw e;
        }
    }

    /** Sends the init (or reconnect) to the init port. */
    void sendHello(String hello) throws IOException {
        channel.send(nulTerminated(hello), initPort);
    }

    /**
     * Waits for the server's first answer, from any port of the server's host; switches to that
     * port. Null when nothing came in time.
     */
    Datagram awaitReply(long timeoutNanos) throws IOException {
        long deadline = System.nanoTime() + timeoutNanos;
        while (true) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return null;
            }
            selector.select(Math.max(1, left / 1_000_000));
            selector.selectedKeys().clear();
            in.clear();
            SocketAddress from = channel.receive(in);
            if (from instanceof InetSocketAddress address && address.getAddress().equals(initPort.getAddress())) {
                clientPort = address;
                return datagram();
            }
        }
    }

    /** The port the server talks to this client from (after {@link #awaitReply}). */
    InetSocketAddress clientPort() {
        return clientPort;
    }

    void send(String message) throws IOException {
        channel.send(nulTerminated(message), clientPort);
    }

    /**
     * The next datagram from the server if one is waiting, else null; never blocks. Datagrams from
     * elsewhere are dropped, a bounded number per call, so a flood of them cannot keep the caller
     * from its timeouts.
     */
    Datagram poll() throws IOException {
        for (int dropped = 0; dropped < MAX_DROPPED_PER_POLL; dropped++) {
            in.clear();
            SocketAddress from = channel.receive(in);
            if (from == null) {
                return null;
            }
            if (from.equals(clientPort)) {
                return datagram();
            }
        }
        return null;
    }

    /** Waits up to {@code timeoutMillis} for a datagram; null when none came (or {@link #wakeup} was called). */
    Datagram await(long timeoutMillis) throws IOException {
        Datagram waiting = poll();
        if (waiting != null) {
            return waiting;
        }
        selector.select(Math.max(1, timeoutMillis));
        selector.selectedKeys().clear();
        return poll();
    }

    /** Ends a wait early (another thread asks the player to stop). */
    void wakeup() {
        selector.wakeup();
    }

    private Datagram datagram() {
        long now = System.nanoTime();
        in.flip();
        int end = in.limit();
        byte[] array = in.array();
        while (end > 0 && (array[end - 1] == 0 || array[end - 1] == '\n' || array[end - 1] == ' ')) {
            end--;
        }
        byte[] bytes = new byte[end];
        System.arraycopy(array, 0, bytes, 0, end);
        return new Datagram(bytes, now);
    }

    private static ByteBuffer nulTerminated(String message) {
        byte[] text = message.getBytes(StandardCharsets.UTF_8);
        byte[] bytes = new byte[text.length + 1];
        System.arraycopy(text, 0, bytes, 0, text.length);
        return ByteBuffer.wrap(bytes);
    }

    @Override
    public void close() throws IOException {
        try {
            selector.close();
        } finally {
            channel.close();
        }
    }
}
