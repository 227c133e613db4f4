package org.scenes.logproxy;

import java.net.InetAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.function.Consumer;
import org.scenes.internal.convert.LogFormat;

/**
 * Everything the proxy needs.
 *
 * @param bindAddress local address the client-facing ports listen on (wildcard for all)
 * @param routes one per client port (players, and optionally coach and online coach)
 * @param outDirectory where the per-client logs go; created if missing
 * @param idleTimeout a client silent this long is closed and its log completed
 * @param endGrace after {@code time_over} or {@code (bye)}, a session quiet in both
 *     directions this long is closed
 * @param logBufferBytes memory between forwarding and the log writer (see {@link LogRing})
 * @param maxClients clients served at once; datagrams from further new addresses are dropped,
 *     so a flood of strange senders cannot exhaust sockets or memory
 * @param events one line per notable event (client seen, log completed, errors)
 */
public record ProxyConfig(InetAddress bindAddress, List<Route> routes, Path outDirectory, LogFormat format,
        Duration idleTimeout, Duration endGrace, int logBufferBytes, int maxClients, Consumer<String> events) {
    public static final int DEFAULT_LOG_BUFFER_BYTES = 64 << 20;
    /** A full game (22 players, 2 coaches, a trainer) with room for reconnections. */
    public static final int DEFAULT_MAX_CLIENTS = 64;
    /** Room for the largest UDP datagram, twice, plus record headers. */
    static final int MIN_LOG_BUFFER_BYTES = 1 << 18;

    public ProxyConfig {
        routes = List.copyOf(routes);
        if (routes.isEmpty()) {
            throw new IllegalArgumentException("no port to listen on");
        }
        if (idleTimeout.isNegative() || idleTimeout.isZero()) {
            throw new IllegalArgumentException("idle timeout must be positive: " + idleTimeout);
        }
        if (endGrace.isNegative() || endGrace.isZero()) {
            throw new IllegalArgumentException("end grace must be positive: " + endGrace);
        }
        if (format.extension() == null) {
            throw new IllegalArgumentException("the proxy writes " + LogFormat.NATIVE.label() + " or " + LogFormat.LSF.label()
                    + " logs, not " + format.label());
        }
        if (maxClients < 1) {
            throw new IllegalArgumentException("max clients must be positive: " + maxClients);
        }
        for (Route route : routes) {
            for (Route other : routes) {
                if (route.listenPort() != 0 && other.server().getPort() == route.listenPort()
                        && isLocal(other.server().getAddress(), bindAddress)) {
                    throw new IllegalArgumentException("the server " + other.server().getHostString() + ":"
                            + other.server().getPort() + " is the proxy's own port " + route.listenPort()
                            + ": it would forward every datagram to itself");
                }
            }
        }
        if (logBufferBytes < MIN_LOG_BUFFER_BYTES) {
            throw new IllegalArgumentException("log buffer must be at least " + MIN_LOG_BUFFER_BYTES + " bytes");
        }
    }

    /** Whether {@code address} is this machine as seen from a proxy bound to {@code bind}. */
    private static boolean isLocal(InetAddress address, InetAddress bind) {
        boolean reachesListener = bind.isAnyLocalAddress() || bind.equals(address)
                || (bind.isLoopbackAddress() && address.isLoopbackAddress());
        if (!reachesListener) {
            return false;
        }
        try {
            return address.isLoopbackAddress() || address.isAnyLocalAddress()
                    || NetworkInterface.getByInetAddress(address) != null;
        } catch (SocketException e) {
            return false;
        }
    }
}
