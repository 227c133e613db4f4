package org.scenes.fakeserver;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.zip.CRC32;
import org.scenes.internal.proxylog.Direction;
import org.scenes.internal.proxylog.ProxyLogLine;
import org.scenes.logproxy.ClientKind;
import org.scenes.internal.convert.LogFormat;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.ProxyStats;
import org.scenes.logproxy.Route;

/**
 * Load run of the logging proxy: N clients play C cycles at full rate (no 100 ms pause: each
 * cycle every client sends a command and gets a {@code see} and a {@code sense_body} back, and
 * the next cycle starts as soon as all have theirs). Prints throughput, the heap after a full GC
 * and the resident set every few cycles, and checks every log against checksums of what was
 * sent (nothing is kept in memory but counters, so the process's memory is the proxy's).
 *
 * <pre>gradle :tests:proxyBench -PbenchArgs="--load --clients 24 --cycles 6000"</pre>
 */
final class ProxyLoad {
    private static final long CYCLE_TIMEOUT_NANOS = 2_000_000_000L;

    private final int clients;
    private final int cycles;
    private final int sampleEvery;
    private final byte[] seeBody;

    ProxyLoad(int clients, int cycles, int sampleEvery, String seeBody) {
        this.clients = clients;
        this.cycles = cycles;
        this.sampleEvery = sampleEvery;
        this.seeBody = seeBody.getBytes(StandardCharsets.US_ASCII);
    }

    /** Running count and checksum of one direction of one client's traffic, as the log holds it. */
    private static final class Tally {
        final CRC32 crc = new CRC32();
        long count;

        void add(ByteBuffer datagram) {
            int end = datagram.limit();
            while (end > datagram.position() && datagram.get(end - 1) == 0) {
                end--;
            }
            ByteBuffer unpadded = datagram.duplicate();
            unpadded.limit(end);
            crc.update(unpadded);
            count++;
        }

        void add(byte[] message) {
            crc.update(message);
            count++;
        }

        boolean same(Tally other) {
            return count == other.count && crc.getValue() == other.crc.getValue();
        }
    }

    /** A server that answers each command with a see and a sense_body and keeps only tallies. */
    private final class LoadServer implements AutoCloseable {
        final DatagramChannel initPort;
        final Selector selector = Selector.open();
        final List<Tally> received = new ArrayList<>();
        final List<Tally> sent = new ArrayList<>();
        final ByteBuffer in = ByteBuffer.allocateDirect(1 << 16);
        final ByteBuffer out = ByteBuffer.allocate(1 << 16);
        final Thread thread = new Thread(this::loop, "load-server");
        volatile boolean running = true;

        LoadServer() throws IOException {
            initPort = DatagramChannel.open();
            initPort.setOption(StandardSocketOptions.SO_RCVBUF, 4 << 20);
            initPort.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            initPort.configureBlocking(false);
            initPort.register(selector, SelectionKey.OP_READ, -1);
            thread.setDaemon(true);
            thread.start();
        }

        InetSocketAddress address() throws IOException {
            return (InetSocketAddress) initPort.getLocalAddress();
        }

        private void loop() {
            try {
                while (running) {
                    selector.select(100);
                    for (SelectionKey key : selector.selectedKeys()) {
                        DatagramChannel channel = (DatagramChannel) key.channel();
                        int client = (Integer) key.attachment();
                        for (SocketAddress from = receive(channel); from != null; from = receive(channel)) {
                            if (client < 0) {
                                init(from);
                            } else {
                                received.get(client).add(in.flip());
                                reply(channel, from, client, "(see ", seeBody);
                                reply(channel, from, client, "(sense_body ",
                                        "(view_mode high normal) (stamina 8000 1) (speed 0 0))".getBytes(StandardCharsets.US_ASCII));
                            }
                        }
                    }
                    selector.selectedKeys().clear();
                }
            } catch (IOException e) {
                if (running) {
                    throw new IllegalStateException("load server failed", e);
                }
            }
        }

        private SocketAddress receive(DatagramChannel channel) throws IOException {
            in.clear();
            return channel.receive(in);
        }

        private void init(SocketAddress from) throws IOException {
            int client = received.size();
            DatagramChannel own = DatagramChannel.open();
            own.setOption(StandardSocketOptions.SO_RCVBUF, 1 << 20);
            own.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            own.configureBlocking(false);
            own.register(selector, SelectionKey.OP_READ, client);
            received.add(new Tally());
            sent.add(new Tally());
            received.get(client).add(in.flip());
            send(own, from, client, ("(init l " + (client + 1) + " before_kick_off)\0").getBytes(StandardCharsets.US_ASCII));
        }

        /** {@code (see T BODY}: the time is the client's command count, so each reply differs. */
        private void reply(DatagramChannel channel, SocketAddress to, int client, String head, byte[] body)
                throws IOException {
            out.clear();
            out.put(head.getBytes(StandardCharsets.US_ASCII)).put(Long.toString(received.get(client).count)
                    .getBytes(StandardCharsets.US_ASCII)).put((byte) ' ').put(body).put((byte) 0).flip();
            byte[] bytes = new byte[out.remaining()];
            out.get(bytes);
            send(channel, to, client, bytes);
        }

        private void send(DatagramChannel channel, SocketAddress to, int client, byte[] datagram) throws IOException {
            ByteBuffer bytes = ByteBuffer.wrap(datagram);
            while (channel.send(bytes, to) == 0) {
                Thread.onSpinWait();
            }
            sent.get(client).add(ByteBuffer.wrap(datagram));
        }

        @Override
        public void close() throws IOException {
            running = false;
            FakeSoccerServer.stopLoop(selector, thread);
        }
    }

    /** Returns true when nothing was lost and every log matches. */
    boolean run() throws Exception {
        Path out = Files.createTempDirectory("proxy-load");
        double loadBefore = loadAverage();
        try (LoadServer server = new LoadServer(); Selector selector = Selector.open()) {
            LogProxy proxy = LogProxy.start(new ProxyConfig(InetAddress.getLoopbackAddress(),
                    List.of(new Route(ClientKind.PLAYER, 0, server.address())), out, LogFormat.NATIVE,
                    Duration.ofSeconds(60), Duration.ofSeconds(5), ProxyConfig.DEFAULT_LOG_BUFFER_BYTES,
                    ProxyConfig.DEFAULT_MAX_CLIENTS, line -> { }));
            InetSocketAddress proxyAddress = new InetSocketAddress(InetAddress.getLoopbackAddress(),
                    proxy.listenPort(ClientKind.PLAYER));
            DatagramChannel[] channels = new DatagramChannel[clients];
            Tally[] sent = new Tally[clients];
            Tally[] received = new Tally[clients];
            ByteBuffer in = ByteBuffer.allocateDirect(1 << 16);
            for (int i = 0; i < clients; i++) {
                channels[i] = DatagramChannel.open();
                channels[i].setOption(StandardSocketOptions.SO_RCVBUF, 1 << 20);
                channels[i].bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
                sent[i] = new Tally();
                received[i] = new Tally();
                send(channels[i], proxyAddress, "(init Load (version 9))", sent[i]);
                in.clear();
                channels[i].receive(in); // blocking: the init answer, from the proxy's port
                received[i].add(in.flip());
                channels[i].configureBlocking(false);
                channels[i].register(selector, SelectionKey.OP_READ, i);
            }
            System.out.printf(Locale.ROOT, "%d clients, %d cycles at full rate (a command, a see of %d bytes and a "
                    + "sense_body per client and cycle); Java %s, %d CPUs, load average %.2f%n", clients, cycles,
                    seeBody.length + 12, System.getProperty("java.version"),
                    Runtime.getRuntime().availableProcessors(), loadBefore);
            System.out.println(" cycle  heap-after-gc-MB  heap-committed-MB  rss-MB  datagrams/s");
            sample(0, 0, 0);
            long lost = 0;
            long started = System.nanoTime();
            long blockStart = started;
            long blockDatagrams = 0;
            int[] replies = new int[clients];
            for (int cycle = 1; cycle <= cycles; cycle++) {
                for (int i = 0; i < clients; i++) {
                    send(channels[i], proxyAddress, "(dash 50 " + cycle + ")", sent[i]);
                    replies[i] = 0;
                }
                int waiting = 2 * clients;
                long deadline = System.nanoTime() + CYCLE_TIMEOUT_NANOS;
                while (waiting > 0 && System.nanoTime() < deadline) {
                    selector.select(100);
                    for (SelectionKey key : selector.selectedKeys()) {
                        int client = (Integer) key.attachment();
                        while (true) {
                            in.clear();
                            if (((DatagramChannel) key.channel()).receive(in) == null) {
                                break;
                            }
                            received[client].add(in.flip());
                            if (replies[client]++ < 2) {
                                waiting--;
                            }
                        }
                    }
                    selector.selectedKeys().clear();
                }
                lost += waiting;
                blockDatagrams += 3L * clients;
                if (cycle % sampleEvery == 0 || cycle == cycles) {
                    long now = System.nanoTime();
                    sample(cycle, blockDatagrams, now - blockStart);
                    blockDatagrams = 0;
                    blockStart = System.nanoTime(); // the sample's GC is not part of the next block
                }
            }
            long elapsed = System.nanoTime() - started;
            for (DatagramChannel channel : channels) {
                channel.close();
            }
            proxy.close();
            ProxyStats stats = proxy.stats();
            boolean complete = true;
            for (int i = 0; i < clients; i++) {
                complete &= logMatches(out.resolve("Load_" + (i + 1) + ".log"), sent[i], server.sent.get(i))
                        & server.received.get(i).same(sent[i]) & received[i].same(server.sent.get(i));
            }
            System.out.printf(Locale.ROOT, "%d cycles in %.1f s (with the samples' GCs): %.0f cycles/s, %.0f datagrams/s "
                    + "through the proxy; lost %d; logs %s (%d messages, log buffer peak %.1f MB, %d waits); "
                    + "load average %.2f after%n", cycles, elapsed / 1e9, cycles / (elapsed / 1e9),
                    3.0 * clients * cycles / (elapsed / 1e9), lost, complete ? "complete" : "INCOMPLETE",
                    stats.logged(), stats.logBufferHighWater() / 1e6, stats.logBufferWaits(), loadAverage());
            return lost == 0 && complete;
        } finally {
            try (var files = Files.list(out)) {
                for (Path file : files.toList()) {
                    Files.delete(file);
                }
            }
            Files.delete(out);
        }
    }

    private static void send(DatagramChannel channel, SocketAddress to, String message, Tally tally) throws IOException {
        byte[] bytes = (message + '\0').getBytes(StandardCharsets.US_ASCII);
        while (channel.send(ByteBuffer.wrap(bytes), to) == 0) {
            Thread.onSpinWait();
        }
        tally.add(ByteBuffer.wrap(bytes));
    }

    private static void sample(int cycle, long datagrams, long nanos) {
        System.gc();
        var heap = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage();
        // committed: what the JVM holds for the heap, most of the resident set's changes
        System.out.printf(Locale.ROOT, "%6d  %16.1f  %17.1f  %6.1f  %s%n", cycle, heap.getUsed() / 1e6,
                heap.getCommitted() / 1e6, residentMegabytes(),
                nanos == 0 ? "-" : String.format(Locale.ROOT, "%.0f", datagrams / (nanos / 1e9)));
    }

    /** VmRSS of this process (Linux), or NaN elsewhere. */
    private static double residentMegabytes() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("VmRSS:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", "")) / 1e3;
                }
            }
        } catch (IOException | NumberFormatException e) {
            // not Linux
        }
        return Double.NaN;
    }

    private static double loadAverage() {
        return ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
    }

    private static boolean logMatches(Path file, Tally toServer, Tally toClient) throws IOException {
        Tally c2s = new Tally();
        Tally s2c = new Tally();
        try (BufferedReader reader = new BufferedReader(new InputStreamReader(Files.newInputStream(file), StandardCharsets.UTF_8))) {
            for (String line = reader.readLine(); line != null; line = reader.readLine()) {
                if (!ProxyLogLine.isComment(line)) {
                    ProxyLogLine parsed = ProxyLogLine.parse(line);
                    (parsed.direction() == Direction.CLIENT_TO_SERVER ? c2s : s2c).add(parsed.message());
                }
            }
        }
        boolean same = c2s.same(toServer) && s2c.same(toClient);
        if (!same) {
            System.out.println(file + ": logged " + c2s.count + " c2s and " + s2c.count + " s2c, sent "
                    + toServer.count + " and " + toClient.count + (c2s.count == toServer.count ? " (checksums differ)" : ""));
        }
        return same;
    }
}
