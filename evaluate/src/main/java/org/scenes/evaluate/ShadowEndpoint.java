package org.scenes.evaluate;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * The server's end of one shadow program's UDP link, on loopback: the first client to send
 * anything is the program (its init), and from then on only its datagrams are taken, queued as
 * text by a reader thread; messages go to it NUL-terminated, as the real server sends them. A
 * server answers an init from a port of its own; this one answers from the port the program
 * wrote to, which a client takes the same way (the port its answer came from).
 */
final class ShadowEndpoint implements AutoCloseable {
    /** Larger than any datagram a client sends. */
    private static final int MAX_DATAGRAM = 1 << 16;

    private final DatagramSocket socket;
    private final LinkedBlockingQueue<String> received = new LinkedBlockingQueue<>();
    private volatile SocketAddress client;

    ShadowEndpoint() throws IOException {
        socket = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        Thread reader = new Thread(this::read, "shadow-endpoint-" + socket.getLocalPort());
        reader.setDaemon(true);
        reader.start();
    }

    String host() {
        return InetAddress.getLoopbackAddress().getHostAddress();
    }

    int port() {
        return socket.getLocalPort();
    }

    /** The next datagram the program sent, waiting up to {@code millis}; null when none came. */
    String take(long millis) throws InterruptedException {
        return received.poll(millis, TimeUnit.MILLISECONDS);
    }

    /** The next datagram the program sent if one is queued, else null. */
    String poll() {
        return received.poll();
    }

    /** Sends a message to the program (after its first datagram). */
    void send(String message) throws IOException {
        byte[] text = message.getBytes(StandardCharsets.UTF_8);
        byte[] bytes = new byte[text.length + 1];
        System.arraycopy(text, 0, bytes, 0, text.length);
        socket.send(new DatagramPacket(bytes, bytes.length, client));
    }

    private void read() {
        byte[] buffer = new byte[MAX_DATAGRAM];
        DatagramPacket packet = new DatagramPacket(buffer, buffer.length);
        while (!socket.isClosed()) {
            try {
                packet.setLength(buffer.length);
                socket.receive(packet);
            } catch (SocketException closed) {
                return;
            } catch (IOException e) {
                continue;
            }
            if (client == null) {
                client = packet.getSocketAddress();
            } else if (!client.equals(packet.getSocketAddress())) {
                continue;
            }
            int end = packet.getLength();
            while (end > 0 && (buffer[end - 1] == 0 || buffer[end - 1] == '\n' || buffer[end - 1] == ' ')) {
                end--;
            }
            received.add(new String(buffer, 0, end, StandardCharsets.UTF_8));
        }
    }

    @Override
    public void close() {
        socket.close();
    }
}
