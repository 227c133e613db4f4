package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.scenes.internal.convert.LogFormat;
import org.scenes.logproxy.ClientKind;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.ProxyStats;
import org.scenes.logproxy.Route;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes proxy}: records agents playing, one log per client. */
@Command(name = "proxy", mixinStandardHelpOptions = true,
        description = {"Logging proxy: clients connect here instead of to the soccer server; every datagram is "
                + "forwarded both ways and written to one log per client (<team>_<unum>, <team>_coach, trainer).",
                "Runs until SIGINT/SIGTERM; every received message is in the logs when it exits."})
final class ProxyCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Option(names = "--server", required = true, paramLabel = "HOST:PORT",
            description = "The soccer server's player port, e.g. localhost:6000.")
    String server;

    @Option(names = "--listen", required = true, paramLabel = "PORT", description = "Port players connect to.")
    int listen;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Directory for the logs (created if missing).")
    Path out;

    @Option(names = "--format", paramLabel = "native|lsf", defaultValue = "native",
            description = "native: time, direction, escaped message per line (.log); lsf: classic layout (.lsf). Default: ${DEFAULT-VALUE}.")
    String format;

    @Option(names = "--coach-listen", paramLabel = "PORT", description = "Also proxy the offline coach (trainer) on this port.")
    Integer coachListen;

    @Option(names = "--coach-server", paramLabel = "HOST:PORT", description = "Server's coach port (default: server port + 1).")
    String coachServer;

    @Option(names = "--olcoach-listen", paramLabel = "PORT", description = "Also proxy online coaches on this port.")
    Integer onlineCoachListen;

    @Option(names = "--olcoach-server", paramLabel = "HOST:PORT", description = "Server's online coach port (default: server port + 2).")
    String onlineCoachServer;

    @Option(names = "--bind", paramLabel = "HOST", defaultValue = "0.0.0.0",
            description = "Local address the client ports listen on. Default: ${DEFAULT-VALUE}.")
    String bind;

    @Option(names = "--idle-timeout", paramLabel = "SECONDS", defaultValue = "30",
            description = "Close a client silent this long and complete its log. Default: ${DEFAULT-VALUE}.")
    double idleTimeout;

    @Option(names = "--end-grace", paramLabel = "SECONDS", defaultValue = "2",
            description = "After time_over or (bye), close a client once quiet both ways this long. Default: ${DEFAULT-VALUE}.")
    double endGrace;

    @Option(names = "--log-buffer-mb", paramLabel = "MB", defaultValue = "64",
            description = "Memory between forwarding and the log writer. Default: ${DEFAULT-VALUE}.")
    int logBufferMb;

    @Option(names = "--max-clients", paramLabel = "N", defaultValue = "" + ProxyConfig.DEFAULT_MAX_CLIENTS,
            description = "Clients served at once; datagrams from further new addresses are dropped. Default: ${DEFAULT-VALUE}.")
    int maxClients;

    @Option(names = "--games", paramLabel = "N",
            description = "Stop by itself once N games have ended (every client gone after time_over or bye), so a recipe"
                    + " finishes on its own. Default: run until SIGINT/SIGTERM.")
    Integer games;

    @Override
    public Integer call() throws IOException, InterruptedException {
        if (games != null && games < 1) {
            throw new UsageException("--games must be at least 1, not " + games);
        }
        PrintWriter console = spec.commandLine().getOut();
        InetSocketAddress playerServer = address("--server", server, -1);
        List<Route> routes = new ArrayList<>();
        routes.add(new Route(ClientKind.PLAYER, port("--listen", listen), playerServer));
        if (coachListen != null) {
            routes.add(new Route(ClientKind.COACH, port("--coach-listen", coachListen),
                    address("--coach-server", coachServer, playerServer.getPort() + 1, playerServer)));
        }
        if (onlineCoachListen != null) {
            routes.add(new Route(ClientKind.ONLINE_COACH, port("--olcoach-listen", onlineCoachListen),
                    address("--olcoach-server", onlineCoachServer, playerServer.getPort() + 2, playerServer)));
        }
        if (idleTimeout <= 0 || endGrace <= 0) {
            throw new UsageException("--idle-timeout and --end-grace must be positive");
        }
        if (logBufferMb < 1 || logBufferMb > 1024) {
            throw new UsageException("--log-buffer-mb must be between 1 and 1024, not " + logBufferMb);
        }
        if (maxClients < 1) {
            throw new UsageException("--max-clients must be positive, not " + maxClients);
        }
        InetAddress bindAddress;
        try {
            bindAddress = InetAddress.getByName(bind);
        } catch (UnknownHostException e) {
            throw new UsageException("--bind: unknown host " + bind);
        }
        ProxyConfig config;
        try {
            config = new ProxyConfig(bindAddress, routes, out, logFormat(), seconds(idleTimeout),
                    seconds(endGrace), logBufferMb << 20, maxClients, line -> {
                        synchronized (console) {
                            console.println(line);
                            console.flush();
                        }
                    });
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        LogProxy proxy = LogProxy.start(config);
        CountDownLatch stopped = new CountDownLatch(1);
        AtomicBoolean closed = new AtomicBoolean();
        AtomicBoolean clean = new AtomicBoolean();
        Runnable stop = () -> {
            if (!closed.compareAndSet(false, true)) {
                return;
            }
            try {
                proxy.close();
                clean.set(true);
            } catch (IOException e) {
                System.err.println("scenes: " + e.getMessage());
            } finally {
                summary(console, proxy.stats());
                stopped.countDown();
            }
        };
        // Ctrl-C and SIGTERM are the documented way to stop: a clean and complete shutdown exits 0
        StopSignals.install("scenes-proxy", stop, stopped);
        // only now "Ctrl-C to stop": a signal from here on is handled
        for (Route route : routes) {
            console.printf("%s: %s:%d -> %s%n", route.kind().name().toLowerCase(Locale.ROOT).replace('_', ' '),
                    bind, proxy.listenPort(route.kind()), route.server());
        }
        console.printf("logging to %s (%s); Ctrl-C to stop%n", out, format);
        console.flush();
        while (!stopped.await(200, TimeUnit.MILLISECONDS)) {
            if (games != null && proxy.gamesEnded() >= games) {
                console.printf("%d game%s ended: stopping%n", games, games == 1 ? "" : "s");
                new Thread(stop, "scenes-proxy-games-ended").start();
                stopped.await();
            }
        }
        return clean.get() ? ExitCodes.OK : ExitCodes.FAILURE;
    }

    private static void summary(PrintWriter console, ProxyStats stats) {
        synchronized (console) {
            console.printf("forwarded %d to server, %d to clients (%d not forwarded); %d messages logged for %d clients; "
                    + "log buffer peak %.1f MB, %d waits; %d log errors%n", stats.toServer(), stats.toClients(),
                    stats.notForwarded(), stats.logged(), stats.sessionsClosed(), stats.logBufferHighWater() / 1e6,
                    stats.logBufferWaits(), stats.logErrors());
            console.flush();
        }
    }

    private LogFormat logFormat() {
        return switch (format.toLowerCase(Locale.ROOT)) {
            case "native" -> LogFormat.NATIVE;
            case "lsf" -> LogFormat.LSF;
            default -> throw new UsageException("--format: expected native or lsf, not '" + format + "'");
        };
    }

    private static Duration seconds(double value) {
        return Duration.ofNanos(Math.round(value * 1e9));
    }

    private static int port(String option, int value) {
        if (value < 0 || value > 65535) {
            throw new UsageException(option + ": port out of range: " + value);
        }
        return value;
    }

    private static InetSocketAddress address(String option, String value, int defaultPort, InetSocketAddress fallback) {
        if (value == null) {
            return new InetSocketAddress(fallback.getAddress(), defaultPort);
        }
        return address(option, value, -1);
    }

    /** Parses HOST:PORT (or [IPv6]:PORT). */
    static InetSocketAddress address(String option, String value, int defaultPort) {
        int colon = value.lastIndexOf(':');
        if (colon <= 0 || colon == value.length() - 1) {
            throw new UsageException(option + ": expected HOST:PORT, not '" + value + "'");
        }
        String host = value.substring(0, colon);
        if (host.startsWith("[") && host.endsWith("]")) {
            host = host.substring(1, host.length() - 1);
        }
        int port;
        try {
            port = Integer.parseInt(value.substring(colon + 1));
        } catch (NumberFormatException e) {
            throw new UsageException(option + ": bad port in '" + value + "'");
        }
        port(option, port);
        InetSocketAddress address = new InetSocketAddress(host, port);
        if (address.isUnresolved()) {
            throw new UsageException(option + ": unknown host '" + host + "'");
        }
        return address;
    }
}
