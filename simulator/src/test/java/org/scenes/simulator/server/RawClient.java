package org.scenes.simulator.server;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/** A bare UDP socket for protocol tests: sends text, receives text, remembers the server's port for it. */
final class RawClient implements AutoCloseable {
    private final DatagramSocket socket;
    private final InetSocketAddress initPort;
    SocketAddress playerPort;
    SocketAddress lastFrom;

    RawClient(int port) throws IOException {
        socket = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        socket.setSoTimeout(3000);
        initPort = new InetSocketAddress("127.0.0.1", port);
    }

    void toInitPort(String text) throws IOException {
        send(text, initPort, true);
    }

    void send(String text) throws IOException {
        send(text, playerPort, true);
    }

    void sendWithoutNul(String text) throws IOException {
        send(text, playerPort, false);
    }

    private void send(String text, SocketAddress to, boolean nul) throws IOException {
        byte[] bytes = (nul ? text + "\0" : text).getBytes(StandardCharsets.UTF_8);
        socket.send(new DatagramPacket(bytes, bytes.length, to));
    }

    /** The next message, without its NUL; null after 3 s of silence. */
    String receive() throws IOException {
        byte[] buffer = new byte[16384];
        DatagramPacket packet = new DatagramPacket(buffer, buffer.length);
        try {
            socket.receive(packet);
        } catch (SocketTimeoutException e) {
            return null;
        }
        lastFrom = packet.getSocketAddress();
        int length = packet.getLength();
        while (length > 0 && buffer[length - 1] == 0) {
            length--;
        }
        return new String(buffer, 0, length, StandardCharsets.UTF_8);
    }

    /** Sends the init and reads the answer and, when accepted, the three parameter messages. */
    List<String> init(String init) throws IOException {
        toInitPort(init);
        List<String> got = new ArrayList<>();
        String reply = receive();
        got.add(reply);
        if (reply != null && reply.startsWith("(init ")) {
            playerPort = lastFrom;
            for (int i = 0; i < 3; i++) {
                got.add(receive());
            }
        }
        return got;
    }

    /** Messages until one starts with {@code prefix} (included), at most {@code limit}. */
    List<String> until(String prefix, int limit) throws IOException {
        List<String> got = new ArrayList<>();
        for (int i = 0; i < limit; i++) {
            String message = receive();
            if (message == null) {
                break;
            }
            got.add(message);
            if (message.startsWith(prefix)) {
                break;
            }
        }
        return got;
    }

    @Override
    public void close() {
        socket.close();
    }
}
