package org.scenes.evaluate;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import org.scenes.api.Side;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.ProtocolException;

/**
 * A UDP relay on loopback between an external team's players and the server, so that a game of
 * two external teams can be watched: the first team is given the relay's port, and what the
 * server tells its players (which side and number each was given, the clock, the referee) goes to
 * a {@link LiveArena.Scoreboard} on its way. Each client address gets an upstream socket of its
 * own (the server tells players apart by address), which follows the server's port switch: after
 * the server answered an init from a port of its own, that player's datagrams go there. The
 * players hear everything from the relay's port, which a client takes as the server's own.
 *
 * <p>An init the server has not answered is sent again every second, as our runtime does: a
 * server restarted for each game (rcssserver in a loop) is not listening for a moment between
 * games, and a client such as the classic Krislet says its init only once.
 */
final class TeamRelay implements AutoCloseable {
    /** Larger than any datagram either side sends. */
    private static final int MAX_DATAGRAM = 1 << 16;
    private static final long HELLO_AGAIN_NANOS = 1_000_000_000L;
    private static final long SELECT_MILLIS = 100;

    private final InetSocketAddress server;
    private final LiveArena.Scoreboard board;
    private final Selector selector;
    private final DatagramChannel listening;
    private final Map<SocketAddress, Player> players = new HashMap<>();
    private final MessageParser parser = new MessageParser();
    private final ByteBuffer buffer = ByteBuffer.allocate(MAX_DATAGRAM);
    private final AtomicInteger accepted = new AtomicInteger();
    private final AtomicReference<Side> firstSide = new AtomicReference<>();
    private final Thread thread;
    private volatile long lastHeard = System.nanoTime();
    private volatile boolean closed;

    /** One client of the team: its address and its own socket towards the server. */
    private static final class Player {
        final SocketAddress client;
        final DatagramChannel upstream;
        SocketAddress serverPort;
        byte[] hello;
        long helloSent;
        Side side;
        int unum;

        Player(SocketAddress client, DatagramChannel upstream, SocketAddress serverPort) {
            this.client = client;
            this.upstream = upstream;
            this.serverPort = serverPort;
        }
    }

    /**
     * @param server the server's init port
     * @param board told what the team's players hear from the server
     */
    TeamRelay(InetSocketAddress server, LiveArena.Scoreboard board) throws IOException {
        if (server.isUnresolved()) {
            throw new IOException("unknown host '" + server.getHostString() + "'");
        }
        this.server = server;
        this.board = board;
        selector = Selector.open();
        listening = DatagramChannel.open();
        try {
            listening.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            listening.configureBlocking(false);
            listening.register(selector, SelectionKey.OP_READ);
        } catch (IOException e) {
            listening.close();
            selector.close();
            throw e;
        }
        thread = new Thread(this::relay, "team-relay-" + port());
        thread.setDaemon(true);
        thread.start();
    }

    /** The address the team's command is given as the server's ({@code {host}}). */
    String host() {
        return InetAddress.getLoopbackAddress().getHostAddress();
    }

    /** The port the team's command is given as the server's ({@code {port}}). */
    int port() {
        return listening.socket().getLocalPort();
    }

    /** Players of the team whose init the server answered with a side. */
    int accepted() {
        return accepted.get();
    }

    /** The side the server gave the team's first accepted player, or null before. */
    Side side() {
        return firstSide.get();
    }

    /** When the server last sent the team anything (System.nanoTime). */
    long lastHeard() {
        return lastHeard;
    }

    private void relay() {
        while (!closed) {
            try {
                selector.select(SELECT_MILLIS);
                for (SelectionKey key : selector.selectedKeys()) {
                    if (key.channel() == listening) {
                        fromPlayers();
                    } else {
                        fromServer((Player) key.attachment());
                    }
                }
                selector.selectedKeys().clear();
                helloAgain();
            } catch (ClosedSelectorException e) {
                return;
            } catch (IOException e) {
                // one datagram lost (UDP loses some anyway); a network that stays down shows as the server's silence
                selector.selectedKeys().clear();
            }
        }
    }

    private void fromPlayers() throws IOException {
        while (true) {
            buffer.clear();
            SocketAddress from = listening.receive(buffer);
            if (from == null) {
                return;
            }
            buffer.flip();
            Player player = players.get(from);
            if (player == null) {
                DatagramChannel upstream = DatagramChannel.open();
                upstream.bind(null);
                upstream.configureBlocking(false);
                player = new Player(from, upstream, server);
                upstream.register(selector, SelectionKey.OP_READ, player);
                players.put(from, player);
            }
            if (player.side == null && (startsWith(buffer, "(init") || startsWith(buffer, "(reconnect"))) {
                player.hello = new byte[buffer.remaining()];
                buffer.duplicate().get(player.hello);
                player.helloSent = System.nanoTime();
            }
            player.upstream.send(buffer, player.serverPort);
        }
    }

    private void fromServer(Player player) throws IOException {
        while (true) {
            buffer.clear();
            SocketAddress from = player.upstream.receive(buffer);
            if (from == null) {
                return;
            }
            if (!(from instanceof InetSocketAddress address) || !address.getAddress().equals(server.getAddress())) {
                continue;
            }
            buffer.flip();
            lastHeard = System.nanoTime();
            String text = text(buffer);
            if (player.side == null) {
                Message parsed = parse(text);
                if (parsed instanceof InitReply init && init.side() != null) {
                    player.side = init.side();
                    player.unum = init.uniformNumber();
                    player.serverPort = from;
                    player.hello = null;
                    firstSide.compareAndSet(null, init.side());
                    accepted.incrementAndGet();
                }
            }
            if (player.side != null) {
                try {
                    board.heard(player.side, player.unum, text, parser);
                } catch (ProtocolException malformed) {
                    // not the scoreboard's business: the player gets it as sent
                }
            }
            listening.send(buffer, player.client);
        }
    }

    private void helloAgain() throws IOException {
        long now = System.nanoTime();
        for (Player player : players.values()) {
            if (player.side == null && player.hello != null && now - player.helloSent >= HELLO_AGAIN_NANOS) {
                player.upstream.send(ByteBuffer.wrap(player.hello), server);
                player.helloSent = now;
            }
        }
    }

    private Message parse(String text) {
        try {
            return parser.parse(text);
        } catch (ProtocolException e) {
            return null;
        }
    }

    private static String text(ByteBuffer buffer) {
        int end = buffer.limit();
        while (end > buffer.position() && buffer.get(end - 1) == 0) {
            end--;
        }
        return new String(buffer.array(), buffer.position(), end - buffer.position(), StandardCharsets.UTF_8);
    }

    private static boolean startsWith(ByteBuffer buffer, String head) {
        if (buffer.remaining() < head.length()) {
            return false;
        }
        for (int i = 0; i < head.length(); i++) {
            if (buffer.get(buffer.position() + i) != head.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    @Override
    public void close() {
        closed = true;
        selector.wakeup();
        try {
            thread.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        for (SelectionKey key : selector.keys()) {
            try {
                key.channel().close();
            } catch (IOException e) {
                // closing: nothing more to relay
            }
        }
        try {
            selector.close();
        } catch (IOException e) {
            // closing
        }
    }
}
