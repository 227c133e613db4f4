package org.scenes.fakeserver;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.SocketTimeoutException;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;

/**
 * A minimal soccer client for tests: sends {@code init} to the server port, follows the reply's
 * source port as real clients do, records every datagram both ways (a receiver thread keeps
 * reading until {@link #close()}).
 */
public final class PlayerClient implements AutoCloseable {
    private final DatagramChannel channel;
    private final List<byte[]> sent = Collections.synchronizedList(new ArrayList<>());
    private final List<byte[]> received = Collections.synchronizedList(new ArrayList<>());
    private final Thread receiver;
    private volatile SocketAddress server;
    private volatile boolean open = true;

    public PlayerClient(InetSocketAddress server) throws IOException {
        this.server = server;
        channel = DatagramChannel.open();
        channel.setOption(StandardSocketOptions.SO_RCVBUF, 4 << 20);
        channel.bind(new InetSocketAddress(server.getAddress(), 0));
        receiver = new Thread(this::receive, "player-client-receiver");
        receiver.setDaemon(true);
        receiver.start();
    }

    /** Sends {@code message} to the init port and waits for the first reply, whose port it then uses. */
    public String init(String message, long timeoutMillis) throws IOException {
        send(message.getBytes(StandardCharsets.UTF_8));
        byte[] reply = awaitReceived(1, timeoutMillis).get(0);
        return new String(reply, StandardCharsets.UTF_8).replace("\0", "");
    }

    public void send(String message) throws IOException {
        send((message + '\0').getBytes(StandardCharsets.UTF_8));
    }

    public synchronized void send(byte[] datagram) throws IOException {
        sent.add(datagram.clone());
        channel.send(ByteBuffer.wrap(datagram), server);
    }

    public List<byte[]> sent() {
        synchronized (sent) {
            return List.copyOf(sent);
        }
    }

    public List<byte[]> received() {
        synchronized (received) {
            return List.copyOf(received);
        }
    }

    public int sentCount() {
        return sent.size();
    }

    public int receivedCount() {
        return received.size();
    }

    /** Waits until at least {@code count} datagrams have arrived. */
    public List<byte[]> awaitReceived(int count, long timeoutMillis) throws IOException {
        long deadline = System.currentTimeMillis() + timeoutMillis;
        while (received.size() < count) {
            if (System.currentTimeMillis() > deadline) {
                throw new SocketTimeoutException("received " + received.size() + " of " + count + " datagrams");
            }
            sleep(2);
        }
        return received();
    }

    private void receive() {
        ByteBuffer buffer = ByteBuffer.allocate(1 << 16);
        try {
            while (open) {
                buffer.clear();
                SocketAddress from = channel.receive(buffer);
                buffer.flip();
                if (received.isEmpty()) {
                    server = from; // the server's port for this client from now on
                }
                received.add(Arrays.copyOf(buffer.array(), buffer.limit()));
            }
        } catch (IOException e) {
            // closed
        }
    }

    static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }

    @Override
    public void close() throws IOException {
        open = false;
        channel.close();
    }
}
