package org.scenes.logproxy;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * The forwarding thread: one selector over the client-facing ports and every client's
 * server-facing socket. Per datagram it forwards first, then copies the bytes into the
 * {@link LogRing}; it never touches the disk.
 */
final class Forwarder implements Runnable {
    private static final int MAX_DATAGRAM = 65_536;
    private static final int SOCKET_BUFFER = 4 << 20;
    /** Datagrams read from one channel before looking at the others, for fairness. */
    private static final int BATCH = 64;
    private static final byte[] TIME_OVER = "referee time_over".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] HEAR = "(hear ".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] BYE = "(bye)".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] INIT = "(init".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] RECONNECT = "(reconnect".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] ERROR = "(error".getBytes(StandardCharsets.US_ASCII);

    private final Selector selector;
    private final List<Listener> listeners = new ArrayList<>();
    private final LogRing ring;
    private final LongSupplier clock;
    private final long start;
    private final long idleNanos;
    private final long endGraceNanos;
    private final long checkEveryNanos;
    private final Consumer<String> events;
    private final int maxClients;
    private final ByteBuffer buffer = ByteBuffer.allocateDirect(MAX_DATAGRAM);
    private final List<Session> sessions = new ArrayList<>();
    private int nextSessionId = 1;
    private long lastCheck;
    private volatile boolean running = true;

    final AtomicLong toServer = new AtomicLong();
    final AtomicLong toClients = new AtomicLong();
    final AtomicLong notForwarded = new AtomicLong();
    final AtomicLong opened = new AtomicLong();
    /** Times the last client went away after its game ended (time_over or bye): games played through. */
    final AtomicLong gamesEnded = new AtomicLong();

    Forwarder(ProxyConfig config, LogRing ring, LongSupplier clock) throws IOException {
        this.ring = ring;
        this.clock = clock;
        this.start = clock.getAsLong();
        this.lastCheck = start;
        this.idleNanos = config.idleTimeout().toNanos();
        this.endGraceNanos = config.endGrace().toNanos();
        this.checkEveryNanos = Math.max(1_000_000L, Math.min(250_000_000L, Math.min(idleNanos, endGraceNanos) / 4));
        this.events = config.events();
        this.maxClients = config.maxClients();
        this.selector = Selector.open();
        try {
            for (Route route : config.routes()) {
                DatagramChannel channel = DatagramChannel.open();
                try {
                    channel.setOption(StandardSocketOptions.SO_RCVBUF, SOCKET_BUFFER);
                    channel.setOption(StandardSocketOptions.SO_SNDBUF, SOCKET_BUFFER);
                    channel.bind(new InetSocketAddress(config.bindAddress(), route.listenPort()));
                } catch (IOException e) {
                    channel.close();
                    throw new IOException("cannot listen on " + config.bindAddress().getHostAddress() + ":"
                            + route.listenPort() + " for " + describe(route.kind()) + ": " + e.getMessage(), e);
                }
                channel.configureBlocking(false);
                Listener listener = new Listener(route, channel);
                listener.outbox.key(channel.register(selector, SelectionKey.OP_READ, listener));
                listeners.add(listener);
            }
        } catch (IOException | RuntimeException e) {
            closeQuietly();
            throw e;
        }
    }

    /** The port a route actually listens on (useful when it asked for port 0). */
    int boundPort(ClientKind kind) throws IOException {
        for (Listener listener : listeners) {
            if (listener.route.kind() == kind) {
                return ((InetSocketAddress) listener.channel.getLocalAddress()).getPort();
            }
        }
        throw new IllegalArgumentException("no " + describe(kind) + " port");
    }

    void stop() {
        running = false;
        selector.wakeup();
    }

    @Override
    public void run() {
        try {
            while (running) {
                selector.select(Math.max(1, checkEveryNanos / 1_000_000L));
                for (SelectionKey key : selector.selectedKeys()) {
                    if (!key.isValid()) {
                        continue;
                    }
                    if (key.isWritable()) {
                        writable(key);
                    }
                    if (key.isValid() && key.isReadable()) {
                        if (key.attachment() instanceof Listener listener) {
                            fromClients(listener);
                        } else {
                            fromServer((Session) key.attachment());
                        }
                    }
                }
                selector.selectedKeys().clear();
                long now = clock.getAsLong();
                if (now - lastCheck >= checkEveryNanos) {
                    lastCheck = now;
                    closeQuietSessions(now);
                }
            }
        } catch (IOException e) {
            events.accept("forwarding stopped: " + e);
        } finally {
            // What the kernel already holds for us still goes through and into the logs.
            for (Listener listener : listeners) {
                fromClients(listener);
            }
            for (Session session : new ArrayList<>(sessions)) {
                fromServer(session);
            }
            for (Session session : new ArrayList<>(sessions)) {
                close(session, "proxy stopped");
            }
            closeQuietly();
        }
    }

    private void writable(SelectionKey key) {
        Outbox outbox = key.attachment() instanceof Listener listener ? listener.outbox : ((Session) key.attachment()).outbox;
        try {
            outbox.flush();
        } catch (IOException e) {
            events.accept("send failed: " + e.getMessage());
        }
    }

    private void fromClients(Listener listener) {
        for (int i = 0; i < BATCH; i++) {
            buffer.clear();
            SocketAddress from;
            try {
                from = listener.channel.receive(buffer);
            } catch (IOException e) {
                events.accept("receive failed on the " + describe(listener.route.kind()) + " port: " + e.getMessage());
                return;
            }
            if (from == null) {
                return;
            }
            long now = clock.getAsLong();
            buffer.flip();
            int end = withoutPadding(buffer);
            // A client only knows the proxy's port, so an init or reconnect it sends is meant for the
            // server's init port: after a server restart its port for this client is gone.
            boolean hello = matches(buffer, 0, end, INIT) || matches(buffer, 0, end, RECONNECT);
            Session session = listener.sessions.get(from);
            if (session == null) {
                // every client starts with init or reconnect: other datagrams from a new address
                // would hold a client slot until the idle timeout, and a few dozen lock clients out
                session = hello ? open(listener, (InetSocketAddress) from, now) : null;
                if (session == null) {
                    if (!hello && notForwarded.getAndIncrement() % 1000 == 0) {
                        events.accept("dropped a datagram from " + from + ": a new client must start with init or reconnect");
                    }
                    continue;
                }
            }
            session.lastFromClient = now;
            session.lastTraffic = now;
            forward(session.outbox, hello ? listener.route.server() : session.serverTarget, toServer);
            ring.publish(RecordType.TO_SERVER, session.id, now - start, buffer, 0, end);
            if (matches(buffer, 0, end, BYE)) {
                session.ending = true;
            }
        }
    }

    private void fromServer(Session session) {
        for (int i = 0; i < BATCH; i++) {
            buffer.clear();
            SocketAddress from;
            try {
                from = session.toServer.receive(buffer);
            } catch (IOException e) {
                events.accept("receive failed for client " + session.client + ": " + e.getMessage());
                return;
            }
            if (from == null) {
                return;
            }
            long now = clock.getAsLong();
            buffer.flip();
            session.lastTraffic = now;
            if (!from.equals(session.serverTarget)) {
                // The server answers init from a port of its own for this client: talk to it from now on.
                session.serverTarget = from;
            }
            forward(session.listener.outbox, session.client, toClients);
            int end = withoutPadding(buffer);
            ring.publish(RecordType.TO_CLIENT, session.id, now - start, buffer, 0, end);
            if (!session.admitted) {
                if (matches(buffer, 0, end, ERROR)) {
                    // the server refused the init (a full team, a bad version): the slot is free at once
                    byte[] reply = new byte[Math.min(end, 200)];
                    buffer.get(0, reply);
                    close(session, "the server refused the client: " + new String(reply, StandardCharsets.US_ASCII).trim());
                    return;
                }
                session.admitted = true;
            }
            if (matches(buffer, 0, end, HEAR) && contains(buffer, end, TIME_OVER)) {
                session.ending = true;
            }
        }
    }

    private void forward(Outbox outbox, SocketAddress target, AtomicLong counter) {
        try {
            if (outbox.send(buffer, target)) {
                counter.incrementAndGet();
                return;
            }
        } catch (IOException e) {
            events.accept("send to " + target + " failed: " + e.getMessage());
        }
        notForwarded.incrementAndGet();
    }

    private Session open(Listener listener, InetSocketAddress client, long now) {
        if (sessions.size() >= maxClients) {
            if (notForwarded.getAndIncrement() % 1000 == 0) {
                events.accept("too many clients (" + maxClients + "): dropping datagrams from " + client);
            }
            return null;
        }
        DatagramChannel channel = null;
        try {
            channel = DatagramChannel.open();
            channel.setOption(StandardSocketOptions.SO_RCVBUF, SOCKET_BUFFER);
            channel.bind(null);
            channel.configureBlocking(false);
            Session session = new Session(nextSessionId++, listener, client, channel, now);
            session.key = channel.register(selector, SelectionKey.OP_READ, session);
            session.outbox.key(session.key);
            listener.sessions.put(client, session);
            sessions.add(session);
            opened.incrementAndGet();
            String description = describe(listener.route.kind()) + " " + client.getAddress().getHostAddress()
                    + ":" + client.getPort();
            ring.publish(RecordType.OPEN, session.id, now - start, description.getBytes(StandardCharsets.UTF_8));
            return session;
        } catch (IOException e) {
            notForwarded.incrementAndGet();
            events.accept("cannot open a socket for client " + client + ": " + e.getMessage());
            if (channel != null) {
                try {
                    channel.close();
                } catch (IOException ignored) {
                    // nothing more to do
                }
            }
            return null;
        }
    }

    private void closeQuietSessions(long now) {
        for (int i = sessions.size() - 1; i >= 0; i--) {
            Session session = sessions.get(i);
            if (session.ending && now - session.lastTraffic >= endGraceNanos) {
                close(session, "game over");
            } else if (now - session.lastFromClient >= idleNanos) {
                close(session, String.format(Locale.ROOT, "client silent for %.1f s", idleNanos / 1e9));
            }
        }
    }

    private void close(Session session, String reason) {
        sessions.remove(session);
        if (sessions.isEmpty() && session.ending) {
            gamesEnded.incrementAndGet();
        }
        session.listener.sessions.remove(session.client);
        int unsent = session.outbox.pendingCount();
        if (unsent > 0) {
            notForwarded.addAndGet(unsent);
            ring.publish(RecordType.NOTE, session.id, clock.getAsLong() - start,
                    (unsent + " datagrams to the server were not sent").getBytes(StandardCharsets.UTF_8));
        }
        session.key.cancel();
        try {
            session.toServer.close();
        } catch (IOException ignored) {
            // the session is over either way
        }
        ring.publish(RecordType.CLOSE, session.id, clock.getAsLong() - start, reason.getBytes(StandardCharsets.UTF_8));
    }

    private void closeQuietly() {
        for (Listener listener : listeners) {
            try {
                listener.channel.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
        try {
            selector.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    /** End of the datagram without its trailing NUL padding. */
    private static int withoutPadding(ByteBuffer datagram) {
        int end = datagram.limit();
        while (end > 0 && datagram.get(end - 1) == 0) {
            end--;
        }
        return end;
    }

    private static boolean matches(ByteBuffer datagram, int from, int end, byte[] prefix) {
        if (end - from < prefix.length) {
            return false;
        }
        for (int i = 0; i < prefix.length; i++) {
            if (datagram.get(from + i) != prefix[i]) {
                return false;
            }
        }
        return true;
    }

    private static boolean contains(ByteBuffer datagram, int end, byte[] word) {
        for (int i = 0; i + word.length <= end; i++) {
            if (matches(datagram, i, end, word)) {
                return true;
            }
        }
        return false;
    }

    static String describe(ClientKind kind) {
        return switch (kind) {
            case PLAYER -> "player";
            case COACH -> "coach";
            case ONLINE_COACH -> "online-coach";
        };
    }
}
