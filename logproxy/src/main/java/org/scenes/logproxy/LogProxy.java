package org.scenes.logproxy;

import java.io.IOException;
import java.nio.file.Files;
import java.time.Instant;

/**
 * The logging proxy: clients talk to it as if it were the soccer server; every datagram is
 * forwarded both ways and recorded in one log per client.
 *
 * <p>Two threads: a forwarding thread (one selector, no disk access) and a log writer, joined
 * by a bounded byte ring ({@link LogRing}). {@link #close()} stops forwarding, then lets the
 * writer drain everything and complete every log; call it from a shutdown hook to survive
 * SIGINT/SIGTERM.
 */
public final class LogProxy implements AutoCloseable {
    private final Forwarder forwarder;
    private final LogWriter writer;
    private final LogRing ring;
    private final Thread forwarding;
    private final Thread writing;
    private boolean closed;

    private LogProxy(ProxyConfig config, ProxyEnvironment environment) throws IOException {
        Files.createDirectories(config.outDirectory());
        if (!Files.isWritable(config.outDirectory())) {
            throw new IOException("output directory is not writable: " + config.outDirectory());
        }
        Instant started = Instant.now();
        ring = new LogRing(config.logBufferBytes());
        forwarder = new Forwarder(config, ring, environment.nanoTime());
        writer = new LogWriter(ring, config.outDirectory(), config.format(), started, config.events(),
                environment.logFiles());
        writing = new Thread(writer, "scenes-proxy-log-writer");
        ring.consumer(writing);
        forwarding = new Thread(forwarder, "scenes-proxy-forwarder");
        writing.start();
        forwarding.start();
    }

    /** Opens the ports and starts forwarding. */
    public static LogProxy start(ProxyConfig config) throws IOException {
        return new LogProxy(config, ProxyEnvironment.system());
    }

    /** The same with another clock or log files (tests of timeouts and disk faults). */
    public static LogProxy start(ProxyConfig config, ProxyEnvironment environment) throws IOException {
        return new LogProxy(config, environment);
    }

    /** The local port clients of this kind should talk to. */
    public int listenPort(ClientKind kind) throws IOException {
        return forwarder.boundPort(kind);
    }

    /**
     * How many times every client has gone after its game ended ({@code time_over} heard or
     * {@code (bye)} sent): the games played through this proxy, one after another.
     */
    public long gamesEnded() {
        return forwarder.gamesEnded.get();
    }

    public ProxyStats stats() {
        return new ProxyStats(forwarder.toServer.get(), forwarder.toClients.get(), forwarder.notForwarded.get(),
                writer.logged.get(), forwarder.opened.get(), writer.closed.get(), ring.highWater(), ring.waits(),
                writer.errors.get());
    }

    /**
     * Stops forwarding, writes every message received so far and completes every log. Safe to
     * call more than once and from a shutdown hook.
     *
     * @throws IOException if any log could not be written (the first error; see the events)
     */
    @Override
    public synchronized void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        forwarder.stop();
        joinUninterruptibly(forwarding);
        writer.stop(writing);
        joinUninterruptibly(writing);
        IOException error = writer.firstError();
        if (error != null) {
            throw new IOException(writer.errors.get() + " log write error(s), first: " + error.getMessage(), error);
        }
    }

    private static void joinUninterruptibly(Thread thread) {
        boolean interrupted = false;
        while (thread.isAlive()) {
            try {
                thread.join();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }
}
