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
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.scenes.internal.convert.LogFormat;
import org.scenes.internal.proxylog.Direction;
import org.scenes.internal.proxylog.ProxyLogLine;
import org.scenes.logproxy.ClientKind;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.ProxyStats;
import org.scenes.logproxy.Route;

/**
 * Latency benchmark of the logging proxy on loopback: N clients each send M commands per
 * 100 ms cycle to the fake server, which answers each with a {@code see} message built from a
 * real log; the round trip is measured talking to the server directly and through the proxy, in
 * alternating blocks of 10 cycles so both see the same background load.
 * Prints p50/p99/max per mode, lost datagrams, and whether the proxy's logs are complete.
 *
 * <pre>gradle :tests:proxyBench -PbenchArgs="--clients 24 --messages 20 --cycles 300"</pre>
 *
 * <p>With {@code --load} first, a load run instead ({@link ProxyLoad}): memory and throughput
 * over a long game at full rate, {@code --load --clients 24 --cycles 6000}.
 */
public final class ProxyBench {
    private static final long CYCLE_NANOS = 100_000_000L;
    /** Cycles per turn of one mode before the other mode's turn. */
    private static final int BLOCK_CYCLES = 10;

    private final int clients;
    private final int messages;
    private final int cycles;
    private final int warmup;
    private final String seeBody;
    /** A proxy already running in another process (port and output directory), or 0. */
    private int externalPort;
    private Path externalOut;
    private int serverPort = 6000;

    private ProxyBench(int clients, int messages, int cycles, int warmup, String seeBody) {
        this.clients = clients;
        this.messages = messages;
        this.cycles = cycles;
        this.warmup = warmup;
        this.seeBody = seeBody;
    }

    public static void main(String[] args) throws Exception {
        int clients = 24;
        int messages = 20;
        int cycles = 300;
        int warmup = 30;
        int externalPort = 0;
        int serverPort = 6000;
        Path externalOut = null;
        boolean load = args.length > 0 && args[0].equals("--load");
        for (int i = load ? 1 : 0; i < args.length; i += 2) {
            if (i + 1 >= args.length) {
                usage("missing value after " + args[i]);
            }
            if (args[i].equals("--external-out")) {
                externalOut = Path.of(args[i + 1]);
                continue;
            }
            int value = Integer.parseInt(args[i + 1]);
            switch (args[i]) {
                case "--external-proxy" -> externalPort = value;
                case "--server-port" -> serverPort = value;
                case "--clients" -> clients = value;
                case "--messages" -> messages = value;
                case "--cycles" -> cycles = value;
                case "--warmup" -> warmup = value;
                default -> usage("unknown option " + args[i]);
            }
        }
        Path log = Path.of(System.getProperty("scenes.shared", "../shared"), "data/krislet/classic-game1/Carleton_1.lsf.gz");
        String see = FakeSoccerServer.recordedSensing(log, 1000).stream()
                .filter(l -> l.startsWith("(see ") && l.length() > 600).findFirst().orElseThrow();
        // "(see T objects...)" -> "objects...)" so the reply can carry a sequence number as its time.
        String body = see.substring(see.indexOf(' ', 5) + 1);
        if (load) {
            System.exit(new ProxyLoad(clients, cycles, Math.max(1, cycles / 12), body).run() ? 0 : 1);
        }
        ProxyBench bench = new ProxyBench(clients, messages, cycles, warmup, body);
        if (externalPort > 0 && externalOut == null) {
            usage("--external-proxy needs --external-out DIR (the proxy's --out, empty)");
        }
        bench.externalPort = externalPort;
        bench.externalOut = externalOut;
        bench.serverPort = serverPort;
        System.out.printf(Locale.ROOT, "%d clients x %d messages per 100 ms cycle, %d cycles (+%d warm-up), "
                + "replies %d bytes; Java %s, %d CPUs%n", clients, messages, cycles, warmup, body.length() + 12,
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors());
        double loadBefore = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        Result[] results = bench.run();
        System.out.printf(Locale.ROOT, "machine load average (1 min) %.2f before, %.2f after%n", loadBefore,
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        Result direct = results[0];
        Result proxied = results[1];
        System.out.println(direct);
        System.out.println(proxied);
        System.out.printf(Locale.ROOT, "proxy adds: p50 %+.3f ms, p99 %+.3f ms%n",
                (proxied.p50 - direct.p50) / 1e6, (proxied.p99 - direct.p99) / 1e6);
        boolean ok = proxied.lost == 0 && direct.lost == 0 && proxied.logsComplete;
        System.exit(ok ? 0 : 1);
    }

    private static void usage(String problem) {
        System.err.println("proxy-bench: " + problem
                + "\nusage: ProxyBench [--load] [--clients N] [--messages N] [--cycles N] [--warmup N]"
                + " [--external-proxy PORT --external-out DIR [--server-port 6000]]"
                + "\n  --external-proxy: measure a proxy running in another process, started as"
                + "\n  scenes proxy --server 127.0.0.1:6000 --listen PORT --out DIR --idle-timeout 10;"
                + "\n  the benchmark's fake server then listens on 127.0.0.1:--server-port for it.");
        System.exit(2);
    }

    private record Result(String mode, long sent, long lost, long p50, long p99, long max, String logs,
            boolean logsComplete) {
        @Override
        public String toString() {
            return String.format(Locale.ROOT, "%-7s round trips %d, lost %d, p50 %.3f ms, p99 %.3f ms, max %.3f ms%s",
                    mode, sent, lost, p50 / 1e6, p99 / 1e6, max / 1e6, logs);
        }
    }

    /** Round-trip times and counts of one mode, gathered over many blocks. */
    private static final class Samples {
        long[] rtt = new long[1 << 16];
        int count;
        long sent;
        long received;

        void add(long nanos) {
            if (count == rtt.length) {
                rtt = Arrays.copyOf(rtt, count * 2);
            }
            rtt[count++] = nanos;
        }

        Result result(String mode, String logs, boolean complete) {
            long[] sorted = Arrays.copyOf(rtt, count);
            Arrays.sort(sorted);
            return new Result(mode, count, sent - received, percentile(sorted, 0.50), percentile(sorted, 0.99),
                    count == 0 ? 0 : sorted[count - 1], logs, complete);
        }
    }

    /**
     * Direct and proxied clients are connected at once but take turns in blocks of
     * {@link #BLOCK_CYCLES} cycles, so both modes see the same background load of the machine.
     */
    private Result[] run() throws Exception {
        boolean external = externalPort > 0;
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of("(sense_body 0)"), external ? serverPort : 0);
                Selector directSelector = Selector.open();
                Selector proxySelector = Selector.open()) {
            server.respondWith((client, datagram) -> reply(datagram));
            Path out = external ? externalOut : Files.createTempDirectory("proxy-bench");
            InetSocketAddress serverAddress = server.address(FakeSoccerServer.Port.PLAYER);
            LogProxy proxy = null;
            InetSocketAddress proxyAddress;
            if (external) {
                proxyAddress = new InetSocketAddress(InetAddress.getLoopbackAddress(), externalPort);
            } else {
                proxy = LogProxy.start(new ProxyConfig(InetAddress.getLoopbackAddress(),
                        List.of(new Route(ClientKind.PLAYER, 0, serverAddress)), out, LogFormat.NATIVE,
                        Duration.ofSeconds(60), Duration.ofSeconds(5), ProxyConfig.DEFAULT_LOG_BUFFER_BYTES,
                        ProxyConfig.DEFAULT_MAX_CLIENTS, line -> { }));
                proxyAddress = new InetSocketAddress(InetAddress.getLoopbackAddress(), proxy.listenPort(ClientKind.PLAYER));
            }
            DatagramChannel[] direct = connect(directSelector, serverAddress, "Direct");
            DatagramChannel[] proxied = connect(proxySelector, proxyAddress, "Bench");
            int total = clients * messages * (cycles + warmup + 2 * BLOCK_CYCLES);
            long[] sentAt = new long[2 * total];
            int[] sequence = {0};
            Samples directSamples = new Samples();
            Samples proxySamples = new Samples();
            exchange(proxySelector, proxied, warmup, sentAt, sequence, null);
            exchange(directSelector, direct, warmup, sentAt, sequence, null);
            for (int block = 0; block * BLOCK_CYCLES < cycles; block++) {
                int length = Math.min(BLOCK_CYCLES, cycles - block * BLOCK_CYCLES);
                if (block % 2 == 0) {
                    exchange(directSelector, direct, length, sentAt, sequence, directSamples);
                    exchange(proxySelector, proxied, length, sentAt, sequence, proxySamples);
                } else {
                    exchange(proxySelector, proxied, length, sentAt, sequence, proxySamples);
                    exchange(directSelector, direct, length, sentAt, sequence, directSamples);
                }
            }
            for (DatagramChannel channel : direct) {
                channel.close();
            }
            for (DatagramChannel channel : proxied) {
                channel.close();
            }
            String logs;
            boolean complete;
            if (external) {
                awaitLogs(out, server);
                complete = logsComplete(out, server);
                logs = "; logs " + (complete ? "complete" : "INCOMPLETE") + " (external proxy)";
            } else {
                proxy.close();
                ProxyStats stats = proxy.stats();
                complete = logsComplete(out, server);
                logs = String.format(Locale.ROOT, "; logs %s (%d messages, not forwarded %d, log buffer peak %.1f MB, %d waits)",
                        complete ? "complete" : "INCOMPLETE", stats.logged(), stats.notForwarded(),
                        stats.logBufferHighWater() / 1e6, stats.logBufferWaits());
                deleteTree(out);
            }
            return new Result[] {directSamples.result("direct", "", true), proxySamples.result("proxy", logs, complete)};
        }
    }

    /** An external proxy completes the logs once the clients fall silent (its idle timeout, above the 5 s pauses of the turns). */
    private static void awaitLogs(Path out, FakeSoccerServer server) throws InterruptedException {
        long deadline = System.nanoTime() + 120_000_000_000L;
        for (FakeSoccerServer.Client client : server.clients()) {
            Path file = out.resolve(client.team + "_" + client.unum + ".log");
            while (client.team.startsWith("Bench") && !Files.exists(file) && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
        }
    }

    private byte[] reply(byte[] command) {
        // "(turn 30 SEQ)" -> "(see SEQ objects...)" : a see message of realistic size carrying the sequence.
        int end = command.length;
        while (end > 0 && (command[end - 1] == 0 || command[end - 1] == ')')) {
            end--;
        }
        int start = end;
        while (start > 0 && command[start - 1] != ' ') {
            start--;
        }
        String sequence = new String(command, start, end - start, StandardCharsets.US_ASCII);
        return ("(see " + sequence + " " + seeBody + "\0").getBytes(StandardCharsets.US_ASCII);
    }

    private DatagramChannel[] connect(Selector selector, InetSocketAddress server, String team) throws IOException {
        DatagramChannel[] channels = new DatagramChannel[clients];
        ByteBuffer buffer = ByteBuffer.allocate(1 << 16);
        for (int i = 0; i < clients; i++) {
            DatagramChannel channel = DatagramChannel.open();
            channel.setOption(StandardSocketOptions.SO_RCVBUF, 1 << 20);
            channel.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            channel.send(ByteBuffer.wrap(("(init " + team + (i / 11) + " (version 9))\0").getBytes(StandardCharsets.US_ASCII)), server);
            buffer.clear();
            SocketAddress replyFrom = channel.receive(buffer); // blocking: the init reply
            channel.connect(replyFrom); // the server's port for this client from now on
            channel.configureBlocking(false);
            channel.register(selector, SelectionKey.OP_READ, i);
            channels[i] = channel;
        }
        return channels;
    }

    /**
     * Sends {@code cycles} cycles of every client's messages on schedule and waits for the
     * replies (2 s at most for stragglers); round trips go to {@code samples} unless null.
     * Sequence numbers are unique over the whole run, so a late reply is never mistaken.
     */
    private void exchange(Selector selector, DatagramChannel[] channels, int cycles, long[] sentAt, int[] sequence,
            Samples samples) throws IOException {
        int perCycle = clients * messages;
        int total = perCycle * cycles;
        long spacing = CYCLE_NANOS / perCycle;
        ByteBuffer in = ByteBuffer.allocate(1 << 16);
        int first = sequence[0];
        long start = System.nanoTime() + 1_000_000L;
        int next = 0;
        int received = 0;
        long endWait = Long.MAX_VALUE;
        while (received < total && System.nanoTime() < endWait) {
            long now = System.nanoTime();
            // Message k of the block is due at start + k * spacing; clients take turns.
            while (next < total && start + next * spacing <= now) {
                DatagramChannel channel = channels[next % clients];
                int number = first + next;
                byte[] command = ("(turn 30 " + number + ")\0").getBytes(StandardCharsets.US_ASCII);
                sentAt[number] = System.nanoTime();
                channel.write(ByteBuffer.wrap(command));
                next++;
                if (next == total) {
                    endWait = System.nanoTime() + 2_000_000_000L; // stragglers, then the rest is lost
                }
            }
            selector.select(1);
            for (SelectionKey key : selector.selectedKeys()) {
                DatagramChannel channel = (DatagramChannel) key.channel();
                while (true) {
                    in.clear();
                    if (channel.receive(in) == null) {
                        break;
                    }
                    long arrived = System.nanoTime();
                    int number = sequence(in);
                    if (number >= first) {
                        received++;
                        if (samples != null) {
                            samples.add(arrived - sentAt[number]);
                        }
                    }
                }
            }
            selector.selectedKeys().clear();
        }
        sequence[0] = first + total;
        if (samples != null) {
            samples.sent += total;
            samples.received += received;
        }
    }

    private static int sequence(ByteBuffer reply) {
        int value = 0;
        for (int i = 5; i < reply.position() && reply.get(i) != ' '; i++) {
            value = value * 10 + (reply.get(i) - '0');
        }
        return value;
    }

    /** Every client's log holds exactly what the client sent and what the server sent it. */
    private static boolean logsComplete(Path out, FakeSoccerServer server) throws IOException {
        boolean complete = true;
        for (FakeSoccerServer.Client client : server.clients()) {
            if (!client.team.startsWith("Bench")) {
                continue; // a direct client
            }
            Path file = out.resolve(client.team + "_" + client.unum + ".log");
            List<byte[]> toServer = new ArrayList<>();
            List<byte[]> toClient = new ArrayList<>();
            try (BufferedReader reader = new BufferedReader(new InputStreamReader(Files.newInputStream(file), StandardCharsets.UTF_8))) {
                for (String line = reader.readLine(); line != null; line = reader.readLine()) {
                    if (!ProxyLogLine.isComment(line)) {
                        ProxyLogLine parsed = ProxyLogLine.parse(line);
                        (parsed.direction() == Direction.CLIENT_TO_SERVER ? toServer : toClient).add(parsed.message());
                    }
                }
            }
            complete &= same(unpadded(client.received()), toServer, file + " c2s");
            complete &= same(unpadded(client.sent()), toClient, file + " s2c");
        }
        return complete;
    }

    private static boolean same(List<byte[]> expected, List<byte[]> logged, String what) {
        if (expected.size() != logged.size()) {
            System.out.println(what + ": " + expected.size() + " datagrams, " + logged.size() + " logged");
            return false;
        }
        for (int i = 0; i < expected.size(); i++) {
            if (!Arrays.equals(expected.get(i), logged.get(i))) {
                System.out.println(what + ": message " + i + " differs");
                return false;
            }
        }
        return true;
    }

    private static List<byte[]> unpadded(List<byte[]> datagrams) {
        List<byte[]> out = new ArrayList<>(datagrams.size());
        for (byte[] datagram : datagrams) {
            int end = datagram.length;
            while (end > 0 && datagram[end - 1] == 0) {
                end--;
            }
            out.add(Arrays.copyOf(datagram, end));
        }
        return out;
    }

    private static long percentile(long[] sorted, double fraction) {
        if (sorted.length == 0) {
            return 0;
        }
        return sorted[Math.min(sorted.length - 1, (int) Math.ceil(fraction * sorted.length) - 1)];
    }

    private static void deleteTree(Path directory) throws IOException {
        try (var files = Files.list(directory)) {
            for (Path file : files.toList()) {
                Files.delete(file);
            }
        }
        Files.delete(directory);
    }
}
