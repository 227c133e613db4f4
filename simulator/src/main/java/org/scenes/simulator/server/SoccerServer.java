package org.scenes.simulator.server;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;
import java.net.PortUnreachableException;
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
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.simulator.Engine;
import org.scenes.simulator.GameRecorder;
import org.scenes.simulator.Seat;

/**
 * The simulator's {@link Engine} served over UDP like rcssserver serves its players: clients
 * send {@code (init ...)} or {@code (reconnect ...)} to the init port and are answered from a
 * port of their own, which takes all their later messages; anything else on the init port gets
 * the server's errors. Once both teams are there (and no one joined for a settling second), or
 * after the teams-wait, the game runs: in real time a cycle every 100 ms, in synchronous mode
 * the next cycle as soon as every player sent {@code (done)} after the server's {@code (think)}
 * (a player that does not answer in time is dropped). Kick-off, halves and time over as the
 * engine's referee decides; then the logs are completed and {@link #run} returns. One thread
 * runs the server; {@link #stop} may be called from any thread.
 */
public final class SoccerServer implements AutoCloseable {
    /** Larger than any datagram a client sends (the server's own buffer is 8 KB). */
    private static final int MAX_DATAGRAM = 8192;
    private static final long CYCLE_NANOS = 100_000_000L;
    private static final long WAIT_SLICE_NANOS = 50_000_000L;
    /**
     * Synchronous mode: when no player joined for this long, the waiting players get a
     * sense_body every cycle, so clients that take a long silence for a lost server stay; a
     * quick succession of joins (and so a deterministic game) gets none. Real time runs its
     * cycles from the start instead.
     */
    private static final long KEEP_ALIVE_AFTER_NANOS = 2_000_000_000L;

    private final ServerConfig config;
    private final Engine engine;
    private final Consumer<String> events;
    private final Selector selector;
    private final DatagramChannel initChannel;
    private final Map<SocketAddress, Remote> byAddress = new HashMap<>();
    private final List<Remote> remotes = new ArrayList<>();
    private final MessageParser parser = new MessageParser();
    private final ByteBuffer in = ByteBuffer.allocate(MAX_DATAGRAM);
    private final GameRecorder recorder;
    private volatile boolean stopRequested;
    private boolean started;
    private long firstJoin;
    private long lastJoin;
    private int joined;
    private int dropped;
    /** Real time: when the next cycle starts, from the server's start on. */
    private long nextCycle;
    private long[] lateness = new long[1024];
    private int latenessCount;

    private SoccerServer(ServerConfig config, Consumer<String> events) throws IOException {
        this.config = config;
        this.events = events;
        this.engine = new Engine(config.cycles(), config.seed());
        this.selector = Selector.open();
        DatagramChannel channel = DatagramChannel.open();
        try {
            channel.bind(new InetSocketAddress(config.host(), config.port()));
            channel.configureBlocking(false);
            channel.register(selector, SelectionKey.OP_READ, null);
        } catch (IOException e) {
            channel.close();
            selector.close();
            throw new IOException("cannot listen on UDP " + config.host() + ":" + config.port() + ": "
                    + e.getMessage(), e);
        }
        this.initChannel = channel;
        GameRecorder opened = null;
        if (config.recordDirectory() != null) {
            try {
                opened = GameRecorder.open(config.recordDirectory(), engine);
            } catch (IOException e) {
                close();
                throw e;
            }
            engine.record(opened);
        }
        this.recorder = opened;
    }

    /** Binds the init port; {@code events} gets one line per connection, drop and phase of the game. */
    public static SoccerServer open(ServerConfig config, Consumer<String> events) throws IOException {
        return new SoccerServer(config, events);
    }

    /** The init port actually bound (useful with port 0). */
    public int port() {
        try {
            return ((InetSocketAddress) initChannel.getLocalAddress()).getPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Asks the running game to stop at the next cycle; its logs are completed. */
    public void stop() {
        stopRequested = true;
        selector.wakeup();
    }

    /** Serves one game; {@code frames} gets the state after every cycle. */
    public ServerResult run(Consumer<GameFrame> frames) throws IOException {
        try {
            awaitTeams();
            long begun = System.nanoTime();
            boolean over = false;
            if (!stopRequested) {
                started = true;
                events.accept("Kick-off preparations: " + describeTeams() + (config.synch() ? ", synchronous mode"
                        : ", real time"));
                over = config.synch() ? playSynchronously(frames) : playInRealTime(frames);
            }
            List<Path> logs = recorder == null ? List.of() : recorder.commit();
            double seconds = (System.nanoTime() - begun) / 1e9;
            events.accept((over ? "Time over: " : "Stopped: ") + engine.team(Side.LEFT) + " " + engine.scoreLeft()
                    + " : " + engine.scoreRight() + " " + engine.team(Side.RIGHT) + " after " + engine.time()
                    + " cycles");
            return new ServerResult(engine.scoreLeft(), engine.scoreRight(), engine.time(), engine.steps(), joined,
                    dropped, !over, percentile(50), percentile(99), percentile(100), seconds, logs);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    private String describeTeams() {
        long left = engine.seats().stream().filter(s -> s.side() == Side.LEFT).count();
        long right = engine.seats().stream().filter(s -> s.side() == Side.RIGHT).count();
        return engine.team(Side.LEFT) + " (" + left + ") against " + engine.team(Side.RIGHT) + " (" + right + ")";
    }

    /** Serves connections until both teams are there and settled, the teams-wait ran out, or a stop. */
    private void awaitTeams() throws IOException {
        if (!config.synch()) {
            awaitTeamsInRealTime();
            return;
        }
        long nextKeepAlive = 0;
        while (!stopRequested) {
            long now = System.nanoTime();
            if (joined > 0 && now - lastJoin >= KEEP_ALIVE_AFTER_NANOS && now >= nextKeepAlive) {
                engine.keepAlive();
                nextKeepAlive = now + CYCLE_NANOS;
            }
            if (teamsReady(now)) {
                awaitFirstMoves();
                return;
            }
            pump(Math.min(now + WAIT_SLICE_NANOS, Math.max(nextKeepAlive, now + 1_000_000)), false);
        }
    }

    /**
     * Synchronous mode, before kick-off preparations: a {@code (think)} to every player and its
     * {@code (done)} awaited (at most the think timeout, no one dropped). A client answers only
     * after what it sent before, its first move included, so on however busy a machine every
     * player starts where it placed itself. (rcssserver, too, sends {@code (think)} before kick-off.)
     */
    private void awaitFirstMoves() throws IOException {
        askToThink();
        pump(System.nanoTime() + config.thinkTimeout().toNanos(), true);
    }

    /** A {@code (think)} to every player, each owing its {@code (done)} again. */
    private void askToThink() {
        for (Remote remote : remotes) {
            remote.done = false;
            send(remote, "(think)");
        }
    }

    /**
     * Real time: the cycles run from the start, as on rcssserver, with the clock at 0; each
     * is a waiting step (sense_body, the sees due, a body command again) until, at a cycle's
     * start, the teams are ready: the game's first step takes that cycle ({@link #nextCycle}).
     */
    private void awaitTeamsInRealTime() throws IOException {
        nextCycle = System.nanoTime();
        while (!stopRequested) {
            long now = System.nanoTime();
            if (now >= nextCycle) {
                if (teamsReady(now)) {
                    return;
                }
                engine.waitingStep();
                nextCycle = following(nextCycle, now - nextCycle);
            }
            pump(nextCycle, false);
        }
    }

    private boolean teamsReady(long now) {
        boolean bothTeams = engine.team(Side.LEFT) != null && engine.team(Side.RIGHT) != null;
        if (bothTeams && now - lastJoin >= config.settle().toNanos()) {
            return true;
        }
        return config.teamsWait() != null && joined > 0 && now - firstJoin >= config.teamsWait().toNanos()
                && now - lastJoin >= Math.min(config.settle().toNanos(), config.teamsWait().toNanos());
    }

    /**
     * The start of the cycle after one due at {@code due} that began {@code late} ns late: like a
     * timer, a cycle that started more than a cycle late is not made up for later.
     */
    private static long following(long due, long late) {
        return due + CYCLE_NANOS + (late > CYCLE_NANOS ? late : 0);
    }

    private boolean playSynchronously(Consumer<GameFrame> frames) throws IOException {
        while (!stopRequested) {
            if (!engine.sense()) {
                return true;
            }
            askToThink();
            long deadline = System.nanoTime() + config.thinkTimeout().toNanos();
            pump(deadline, true);
            for (Remote remote : List.copyOf(remotes)) {
                if (!remote.done) {
                    dropped++;
                    events.accept("Dropped " + remote.seat + ": no (done) within " + config.thinkTimeout().toMillis()
                            + " ms");
                    disconnect(remote, null);
                }
            }
            frames.accept(engine.advance());
        }
        return false;
    }

    private boolean playInRealTime(Consumer<GameFrame> frames) throws IOException {
        long next = nextCycle;
        while (!stopRequested) {
            long late = System.nanoTime() - next;
            recordLateness(late);
            if (!engine.sense()) {
                return true;
            }
            next = following(next, late);
            pump(next, false);
            frames.accept(engine.advance());
        }
        return false;
    }

    private void recordLateness(long nanos) {
        if (latenessCount == lateness.length) {
            lateness = Arrays.copyOf(lateness, latenessCount * 2);
        }
        lateness[latenessCount++] = Math.max(0, nanos);
    }

    /** The nearest-rank percentile of cycle-start lateness in ms; 0 without samples (synchronous mode). */
    private double percentile(double p) {
        if (latenessCount == 0) {
            return 0;
        }
        long[] sorted = Arrays.copyOf(lateness, latenessCount);
        Arrays.sort(sorted);
        int rank = (int) Math.ceil(p / 100 * sorted.length);
        return sorted[Math.max(0, Math.min(sorted.length - 1, rank - 1))] / 1e6;
    }

    /**
     * Handles datagrams until the deadline, or in synchronous mode ({@code untilDone}) until every
     * remote has sent {@code (done)}.
     */
    private void pump(long deadline, boolean untilDone) throws IOException {
        while (!stopRequested) {
            if (untilDone && remotes.stream().allMatch(r -> r.done)) {
                return;
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return;
            }
            int ready = left >= 1_000_000 ? selector.select(left / 1_000_000) : selector.selectNow();
            if (ready == 0) {
                if (left < 1_000_000) {
                    Thread.onSpinWait();
                }
                continue;
            }
            for (SelectionKey key : selector.selectedKeys()) {
                if (key.isValid() && key.isReadable()) {
                    drain((DatagramChannel) key.channel(), (Remote) key.attachment());
                }
            }
            selector.selectedKeys().clear();
        }
    }

    private void drain(DatagramChannel channel, Remote remote) throws IOException {
        while (channel.isOpen()) {
            in.clear();
            SocketAddress from;
            try {
                from = channel.receive(in);
            } catch (PortUnreachableException e) {
                continue;
            }
            if (from == null) {
                return;
            }
            in.flip();
            int length = in.limit();
            boolean terminated = length > 0 && in.get(length - 1) == 0;
            while (length > 0 && in.get(length - 1) == 0) {
                length--;
            }
            if (length == 0) {
                continue;
            }
            String text = new String(in.array(), 0, length, StandardCharsets.UTF_8);
            if (remote == null) {
                atInitPort(from, text);
            } else if (remote.seat != null && from.equals(remote.address)) {
                fromPlayer(remote, text, terminated);
            }
        }
    }

    /** The init port: new players and reconnects; a known client gets only_init_allowed_on_init_port. */
    private void atInitPort(SocketAddress from, String text) throws IOException {
        Remote known = byAddress.get(from);
        if (known != null) {
            send(known, "(error only_init_allowed_on_init_port)");
            return;
        }
        Admission admission = Admission.read(parser, text);
        if (admission.error() != null) {
            reply(from, admission.error());
            return;
        }
        DatagramChannel channel = DatagramChannel.open();
        Remote remote;
        try {
            channel.bind(new InetSocketAddress(config.host(), 0));
            channel.configureBlocking(false);
            channel.setOption(StandardSocketOptions.SO_SNDBUF, 1 << 20);
            remote = new Remote(channel, from);
            channel.register(selector, SelectionKey.OP_READ, remote);
        } catch (IOException e) {
            channel.close();
            reply(from, "(error socket_open_failed)");
            return;
        }
        Consumer<String> out = message -> send(remote, message);
        try {
            if (admission.unum() > 0) {
                Remote previous = remotes.stream().filter(r -> r.seat.team().equals(admission.team())
                        && r.seat.unum() == admission.unum()).findFirst().orElse(null);
                remote.seat = engine.rejoin(admission.team(), admission.unum(), text, out);
                if (previous != null) {
                    forget(previous);
                }
                events.accept("A player (" + admission.team() + " " + admission.unum() + ") reconnected.");
            } else {
                remote.seat = engine.join(admission.team(), admission.version(), admission.goalie(), text, out);
                engine.welcome(remote.seat);
                joined++;
                long now = System.nanoTime();
                firstJoin = joined == 1 ? now : firstJoin;
                lastJoin = now;
                events.accept("A new (v" + admission.version() + ") player (" + admission.team() + " "
                        + remote.seat.unum() + ") connected" + (admission.goalie() ? " as goalie." : "."));
            }
        } catch (Engine.Refused e) {
            channel.close();
            reply(from, e.answer());
            return;
        }
        remotes.add(remote);
        byAddress.put(from, remote);
    }

    private void fromPlayer(Remote remote, String text, boolean terminated) {
        Seat seat = remote.seat;
        if (!terminated && seat.version() >= 8) {
            send(remote, "(warning message_not_null_terminated)");
        }
        String command = text.strip();
        if (command.equals("(bye)")) {
            events.accept("A player (" + seat.team() + " " + seat.unum() + ") left.");
            disconnect(remote, text);
            return;
        }
        if (command.equals("(done)")) {
            engine.note(seat, text);
            remote.done = true;
            return;
        }
        if (engine.answerNow(seat, text)) {
            return;
        }
        engine.received(seat, text);
        if (engine.holdsDone(text)) {
            remote.done = true; // (done) after the cycle's commands in one datagram, as librcsc sends it
        }
        if (!started) {
            // Before kick-off preparations the server executes commands as they arrive, such as the first move.
            engine.executePending(seat);
        }
    }

    private void disconnect(Remote remote, String bye) {
        engine.leave(remote.seat, bye);
        forget(remote);
    }

    private void forget(Remote remote) {
        remotes.remove(remote);
        byAddress.remove(remote.address);
        try {
            remote.channel.close();
        } catch (IOException e) {
            // already gone
        }
    }

    private void send(Remote remote, String message) {
        try {
            remote.channel.send(nulTerminated(message), remote.address);
        } catch (PortUnreachableException e) {
            // the client is gone; silence will drop it in synchronous mode
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private void reply(SocketAddress to, String message) throws IOException {
        initChannel.send(nulTerminated(message), to);
    }

    private static ByteBuffer nulTerminated(String message) {
        byte[] bytes = message.getBytes(StandardCharsets.UTF_8);
        ByteBuffer buffer = ByteBuffer.allocate(bytes.length + 1);
        buffer.put(bytes).put((byte) 0).flip();
        return buffer;
    }

    @Override
    public void close() throws IOException {
        for (Remote remote : List.copyOf(remotes)) {
            forget(remote);
        }
        try {
            if (recorder != null) {
                recorder.close();
            }
        } finally {
            initChannel.close();
            selector.close();
        }
    }
}
