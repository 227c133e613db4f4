package org.scenes.fakeserver;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BiFunction;
import java.util.function.Predicate;
import org.scenes.internal.files.Inputs;

/**
 * A scripted stand-in for rcssserver on loopback. It does the init exchange the way the real
 * server does, answering from a new port dedicated to each client, and then sends what the
 * test (or benchmark) tells it to: recorded {@code see}/{@code sense_body} lines from a real
 * log, or replies computed from what the client sent. It records every datagram both ways.
 *
 * <p>Three init ports, as the real server has: players get {@code (init SIDE UNUM
 * before_kick_off)}, the offline coach {@code (init ok)}, an online coach
 * {@code (init SIDE ok)}. A non-init datagram on an init port gets
 * {@code (error only_init_allowed_on_init_port)}, as from protocol version 8 on.
 */
public final class FakeSoccerServer implements AutoCloseable {
    /** Which init port a datagram arrived on. */
    public enum Port { PLAYER, COACH, ONLINE_COACH }

    private final Selector selector;
    private final Map<Port, DatagramChannel> initPorts = new HashMap<>();
    private final List<Client> clients = new CopyOnWriteArrayList<>();
    private final List<byte[]> strayOnInitPorts = new CopyOnWriteArrayList<>();
    private final List<String> recorded;
    private final Map<String, Integer> numbersByTeam = new HashMap<>();
    private final List<String> sides = new ArrayList<>();
    private final Thread thread;
    private volatile BiFunction<Client, byte[], byte[]> responder;
    private volatile boolean running = true;

    private FakeSoccerServer(List<String> recorded, int playerPort) throws IOException {
        this.recorded = List.copyOf(recorded);
        selector = Selector.open();
        for (Port port : Port.values()) {
            DatagramChannel channel = DatagramChannel.open();
            channel.setOption(StandardSocketOptions.SO_RCVBUF, 4 << 20);
            int number = port == Port.PLAYER || playerPort == 0 ? playerPort : playerPort + port.ordinal();
            channel.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), number));
            channel.configureBlocking(false);
            channel.register(selector, SelectionKey.OP_READ, port);
            initPorts.put(port, channel);
        }
        thread = new Thread(this::loop, "fake-soccer-server");
        thread.setDaemon(true);
        thread.start();
    }

    /** A server that replays the given server messages ({@code see}, {@code sense_body}...). */
    private volatile Predicate<String> refusedTeams = team -> false;

    public static FakeSoccerServer start(List<String> recordedServerMessages) throws IOException {
        return new FakeSoccerServer(recordedServerMessages, 0);
    }

    /** The same on fixed ports: players on {@code playerPort}, coaches on the next two, as rcssserver. */
    public static FakeSoccerServer start(List<String> recordedServerMessages, int playerPort) throws IOException {
        return new FakeSoccerServer(recordedServerMessages, playerPort);
    }

    /** The {@code see} and {@code sense_body} lines of a classic {@code .lsf} log (gzip or not). */
    public static List<String> recordedSensing(Path lsf, int maxLines) throws IOException {
        List<String> lines = new ArrayList<>();
        try (BufferedReader reader = new BufferedReader(new InputStreamReader(Inputs.open(lsf), StandardCharsets.UTF_8))) {
            for (String line = reader.readLine(); line != null && lines.size() < maxLines; line = reader.readLine()) {
                if (line.startsWith("(see ") || line.startsWith("(sense_body ")) {
                    lines.add(line);
                }
            }
        }
        if (lines.isEmpty()) {
            throw new IOException(lsf + ": no see or sense_body line");
        }
        return lines;
    }

    /** Replies to every later (non-init) client datagram with what this returns; null = no reply. */
    /** Inits of teams this accepts are refused with {@code (error no_more_team_or_player_or_goalie)}, as a full server does. */
    public void refuseTeams(Predicate<String> refused) {
        this.refusedTeams = refused;
    }

    public void respondWith(BiFunction<Client, byte[], byte[]> responder) {
        this.responder = responder;
    }

    public InetSocketAddress address(Port port) {
        try {
            return (InetSocketAddress) initPorts.get(port).getLocalAddress();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Clients in the order they connected. */
    public List<Client> clients() {
        return List.copyOf(clients);
    }

    /** Non-init datagrams that arrived on an init port (a proxy that did not follow the switch). */
    public List<byte[]> strayOnInitPorts() {
        return List.copyOf(strayOnInitPorts);
    }

    /** Sends each client its next {@code count} recorded lines, NUL-terminated as the real server does. */
    public void replay(int count) throws IOException {
        for (Client client : clients) {
            for (int i = 0; i < count; i++) {
                String line = recorded.get(client.replayed++ % recorded.size());
                client.send((line + '\0').getBytes(StandardCharsets.UTF_8));
            }
        }
    }

    private void loop() {
        ByteBuffer buffer = ByteBuffer.allocateDirect(1 << 16);
        try {
            while (running) {
                selector.select(100);
                for (SelectionKey key : selector.selectedKeys()) {
                    if (!key.isValid() || !key.isReadable()) {
                        continue;
                    }
                    DatagramChannel channel = (DatagramChannel) key.channel();
                    while (true) {
                        buffer.clear();
                        SocketAddress from = channel.receive(buffer);
                        if (from == null) {
                            break;
                        }
                        buffer.flip();
                        byte[] datagram = new byte[buffer.remaining()];
                        buffer.get(datagram);
                        if (key.attachment() instanceof Port port) {
                            onInitPort(port, (InetSocketAddress) from, datagram);
                        } else {
                            onClientPort((Client) key.attachment(), datagram);
                        }
                    }
                }
                selector.selectedKeys().clear();
            }
        } catch (IOException e) {
            if (running) {
                throw new IllegalStateException("fake server failed", e);
            }
        }
    }

    private void onInitPort(Port port, InetSocketAddress from, byte[] datagram) throws IOException {
        String text = new String(datagram, StandardCharsets.UTF_8).replace("\0", "");
        if (!text.startsWith("(init")) {
            strayOnInitPorts.add(datagram);
            initPorts.get(port).send(ByteBuffer.wrap("(error only_init_allowed_on_init_port)\0".getBytes(StandardCharsets.UTF_8)), from);
            return;
        }
        String[] words = text.substring(1, text.length() - 1).split("[ ()]+");
        String team = words.length > 1 && !words[1].equals("version") ? words[1] : null;
        if (team != null && refusedTeams.test(team)) {
            initPorts.get(port).send(ByteBuffer.wrap("(error no_more_team_or_player_or_goalie)\0".getBytes(StandardCharsets.UTF_8)), from);
            return;
        }
        String reply;
        int unum = 0;
        String side = team == null ? null : side(team);
        if (port == Port.COACH) {
            reply = "(init ok)";
        } else if (port == Port.ONLINE_COACH) {
            reply = "(init " + side + " ok)";
        } else {
            unum = numbersByTeam.merge(team, 1, Integer::sum);
            reply = "(init " + side + " " + unum + " before_kick_off)";
        }
        DatagramChannel own = DatagramChannel.open();
        own.setOption(StandardSocketOptions.SO_RCVBUF, 1 << 20);
        own.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        own.configureBlocking(false);
        Client client = new Client(port, from, own, team, side, unum);
        client.received.add(datagram);
        own.register(selector, SelectionKey.OP_READ, client);
        clients.add(client);
        client.send((reply + '\0').getBytes(StandardCharsets.UTF_8));
    }

    private String side(String team) {
        int index = sides.indexOf(team);
        if (index < 0) {
            sides.add(team);
            index = sides.size() - 1;
        }
        return index == 0 ? "l" : "r";
    }

    private void onClientPort(Client client, byte[] datagram) throws IOException {
        client.received.add(datagram);
        BiFunction<Client, byte[], byte[]> current = responder;
        if (current != null) {
            byte[] reply = current.apply(client, datagram);
            if (reply != null) {
                client.send(reply);
            }
        }
    }

    @Override
    public void close() throws IOException {
        running = false;
        stopLoop(selector, thread);
    }

    /**
     * Ends a selector loop whose running flag was just cleared: wakes it, gives its thread 5 s, then
     * closes every channel registered with the selector (the init ports and the clients') and the selector.
     */
    static void stopLoop(Selector selector, Thread thread) throws IOException {
        if (!selector.isOpen()) {
            return; // stopped already: close twice is allowed
        }
        selector.wakeup();
        try {
            thread.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        for (SelectionKey key : selector.keys()) {
            key.channel().close();
        }
        selector.close();
    }

    /** One client as the server knows it, with everything exchanged, in order. */
    public static final class Client {
        public final Port port;
        /** Where the client's datagrams come from (the proxy's socket for this client, if proxied). */
        public final InetSocketAddress address;
        public final String team;
        public final String side;
        public final int unum;
        private final DatagramChannel channel;
        private final List<byte[]> received = Collections.synchronizedList(new ArrayList<>());
        private final List<byte[]> sent = Collections.synchronizedList(new ArrayList<>());
        private int replayed;

        Client(Port port, InetSocketAddress address, DatagramChannel channel, String team, String side, int unum) {
            this.port = port;
            this.address = address;
            this.channel = channel;
            this.team = team;
            this.side = side;
            this.unum = unum;
        }

        /** Sends from this client's own server port; recorded in {@link #sent()}. */
        public synchronized void send(byte[] datagram) throws IOException {
            sent.add(datagram.clone());
            ByteBuffer bytes = ByteBuffer.wrap(datagram);
            // Non-blocking channel: a full socket buffer takes 0 bytes; retry rather than lose it.
            while (channel.send(bytes, address) == 0 && datagram.length > 0) {
                Thread.onSpinWait();
            }
        }

        /** Every datagram received from the client, init included, as received. */
        public List<byte[]> received() {
            synchronized (received) {
                return List.copyOf(received);
            }
        }

        public int receivedCount() {
            return received.size();
        }

        public int sentCount() {
            return sent.size();
        }

        /** Every datagram sent to the client, init reply included. */
        public List<byte[]> sent() {
            synchronized (sent) {
                return List.copyOf(sent);
            }
        }

        public int serverPort() throws IOException {
            return ((InetSocketAddress) channel.getLocalAddress()).getPort();
        }

        @Override
        public String toString() {
            return port + " " + team + " " + unum + " at " + address + " " + Arrays.asList(received.size(), sent.size());
        }
    }
}
