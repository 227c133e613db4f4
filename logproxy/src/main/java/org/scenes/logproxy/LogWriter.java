package org.scenes.logproxy;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import org.scenes.internal.convert.LogFormat;
import org.scenes.internal.proxylog.Direction;
import org.scenes.internal.proxylog.MessageEscapes;
import org.scenes.internal.proxylog.ProxyLogLine;

/**
 * The log writer thread: drains the {@link LogRing} into one file per client. A client's log is
 * written under a hidden temporary name and renamed once its session ends, to
 * {@code <team>_<unum>}, {@code <team>_coach} or {@code trainer} (learned from the init
 * exchange), never over an existing file.
 */
final class LogWriter implements Runnable {
    private static final long IDLE_PARK_NANOS = 5_000_000L;
    private static final long FLUSH_EVERY_NANOS = 500_000_000L;

    private final LogRing ring;
    private final Path directory;
    private final LogFormat format;
    private final Consumer<String> events;
    private final Instant started;
    private final ProxyEnvironment.LogFiles files;
    private final Map<Integer, SessionLog> sessions = new HashMap<>();
    /** One formatted line; big enough for the largest datagram escaped, plus time and direction. */
    private final byte[] line = new byte[MessageEscapes.maxEscapedLength(1 << 16) + 64];
    final AtomicLong logged = new AtomicLong();
    final AtomicLong closed = new AtomicLong();
    final AtomicLong errors = new AtomicLong();
    private volatile boolean stopping;
    private volatile IOException firstError;
    private long lastFlush = System.nanoTime();

    LogWriter(LogRing ring, Path directory, LogFormat format, Instant started, Consumer<String> events,
            ProxyEnvironment.LogFiles files) {
        this.files = files;
        this.started = started;
        this.ring = ring;
        this.directory = directory;
        this.format = format;
        this.events = events;
    }

    /** Asks the thread to finish: it drains everything already published, then completes every log. */
    void stop(Thread thread) {
        stopping = true;
        LockSupport.unpark(thread);
    }

    IOException firstError() {
        return firstError;
    }

    @Override
    public void run() {
        try {
            while (true) {
                boolean finishing = stopping;
                int drained = ring.drain(this::record);
                flushIfDue();
                if (drained == 0) {
                    if (finishing && ring.isEmpty()) {
                        break;
                    }
                    LockSupport.parkNanos(IDLE_PARK_NANOS);
                }
            }
        } finally {
            for (SessionLog log : sessions.values().toArray(new SessionLog[0])) {
                finish(log, "proxy stopped");
            }
        }
    }

    private void record(int type, int session, long nanos, byte[] data, int offset, int length) {
        try {
            handle(type, session, nanos, data, offset, length);
        } catch (RuntimeException e) {
            // Whatever goes wrong, keep draining: a writer that stops would stall forwarding.
            errors.incrementAndGet();
            events.accept("log writer error: " + e);
        }
    }

    private void handle(int type, int session, long nanos, byte[] data, int offset, int length) {
        switch (type) {
            case RecordType.OPEN -> open(session, nanos, new String(data, offset, length, StandardCharsets.UTF_8));
            case RecordType.TO_SERVER, RecordType.TO_CLIENT -> message(session, nanos,
                    type == RecordType.TO_SERVER ? Direction.CLIENT_TO_SERVER : Direction.SERVER_TO_CLIENT,
                    data, offset, length);
            case RecordType.NOTE -> comment(sessions.get(session), new String(data, offset, length, StandardCharsets.UTF_8));
            case RecordType.CLOSE -> {
                SessionLog log = sessions.get(session);
                if (log != null) {
                    finish(log, new String(data, offset, length, StandardCharsets.UTF_8));
                }
            }
            default -> throw new IllegalStateException("unknown log record type " + type);
        }
    }

    private void open(int session, long nanos, String description) {
        SessionLog log = new SessionLog(session, description);
        sessions.put(session, log);
        try {
            log.temporary = directory.resolve(".session-" + session + "-" + ProcessHandle.current().pid() + ".part");
            log.out = new BufferedOutputStream(files.create(log.temporary), 1 << 16);
            if (format == LogFormat.NATIVE) {
                log.out.write((ProxyLogLine.HEADER + "\n").getBytes(StandardCharsets.UTF_8));
            }
        } catch (IOException e) {
            fail(log, e);
        }
        comment(log, "client " + description);
        // Times are seconds since the proxy started; this anchors them to the wall clock.
        comment(log, "proxy started " + started);
        events.accept("client " + description + " connected");
    }

    private void message(int session, long nanos, Direction direction, byte[] data, int offset, int length) {
        SessionLog log = sessions.get(session);
        if (log == null) {
            return;
        }
        if (!log.identity.complete() && length < 512) {
            String text = new String(data, offset, length, StandardCharsets.UTF_8);
            if (direction == Direction.CLIENT_TO_SERVER) {
                log.identity.fromClient(text);
            } else if (log.identity.fromServer(text)) {
                log.pendingIdentity = true;
            }
        }
        int end = format == LogFormat.NATIVE
                ? ProxyLogLine.write(nanos / 1000, direction, data, offset, length, line)
                : MessageEscapes.escape(data, offset, length, line, 0);
        line[end++] = '\n';
        write(log, line, end);
        log.messages++;
        logged.incrementAndGet();
        if (log.pendingIdentity) {
            log.pendingIdentity = false;
            comment(log, log.identity.description());
            events.accept("client " + log.description + " is " + log.identity.fileStem());
        }
    }

    private void comment(SessionLog log, String text) {
        if (log == null || format != LogFormat.NATIVE) {
            return;
        }
        byte[] comment = ("# " + text.replace('\n', ' ').replace('\r', ' ') + "\n").getBytes(StandardCharsets.UTF_8);
        write(log, comment, comment.length);
    }

    private void write(SessionLog log, byte[] bytes, int length) {
        if (log.out == null) {
            return;
        }
        try {
            log.out.write(bytes, 0, length);
            log.dirty = true;
        } catch (IOException e) {
            fail(log, e);
        }
    }

    private void flushIfDue() {
        long now = System.nanoTime();
        if (now - lastFlush < FLUSH_EVERY_NANOS) {
            return;
        }
        lastFlush = now;
        for (SessionLog log : sessions.values()) {
            if (log.dirty && log.out != null) {
                try {
                    log.out.flush();
                    log.dirty = false;
                } catch (IOException e) {
                    fail(log, e);
                }
            }
        }
    }

    private void finish(SessionLog log, String reason) {
        comment(log, "end " + reason);
        sessions.remove(log.session);
        if (log.out == null) {
            closed.incrementAndGet();
            return;
        }
        try {
            log.out.close();
            log.out = null;
            Path target;
            try {
                target = moveWithoutOverwrite(log.temporary, stem(log));
            } catch (IOException e) {
                // a name the file system refuses: the log is kept under its session number, never left as .part
                target = moveWithoutOverwrite(log.temporary, "session_" + log.session);
                events.accept("client " + log.description + ": cannot name its log " + stem(log) + " ("
                        + e.getMessage() + "); named " + target.getFileName());
            }
            events.accept("client " + log.description + " ended (" + reason + "): " + log.messages
                    + " messages in " + target);
        } catch (IOException e) {
            fail(log, e);
        }
        closed.incrementAndGet();
    }

    private String stem(SessionLog log) {
        String stem = log.identity.fileStem();
        if (stem != null) {
            return stem;
        }
        return "unidentified_" + log.description.replaceAll("[^A-Za-z0-9]+", "_").replaceAll("^_+|_+$", "");
    }

    /** Renames to {@code stem.ext}, or {@code stem-1.ext}, {@code stem-2.ext}... if taken. */
    private Path moveWithoutOverwrite(Path source, String stem) throws IOException {
        for (int suffix = 0; ; suffix++) {
            Path target = directory.resolve(stem + (suffix == 0 ? "" : "-" + suffix) + "." + format.extension());
            if (Files.exists(target)) {
                continue;
            }
            try {
                // Without REPLACE_EXISTING the move fails rather than replace a file created meanwhile.
                return Files.move(source, target);
            } catch (FileAlreadyExistsException e) {
                // taken between the check and the move: try the next suffix
            }
        }
    }

    private void fail(SessionLog log, IOException e) {
        errors.incrementAndGet();
        if (firstError == null) {
            firstError = e;
        }
        events.accept("log error for client " + log.description + ": " + e);
        if (log.out != null) {
            try {
                log.out.close();
            } catch (IOException ignored) {
                // already failing; the first error is the one reported
            }
            log.out = null;
        }
    }

    /** Writer-side state of one client's log. */
    private static final class SessionLog {
        final int session;
        final String description;
        final SessionIdentity identity = new SessionIdentity();
        Path temporary;
        OutputStream out;
        long messages;
        boolean dirty;
        boolean pendingIdentity;

        SessionLog(int session, String description) {
            this.session = session;
            this.description = description;
        }
    }
}
