package org.scenes.internal.files;

import com.github.luben.zstd.ZstdOutputStream;
import java.io.BufferedOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryIteratorException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.GZIPOutputStream;

/**
 * An output file that appears only when complete: bytes go to a temporary file beside the
 * target, which {@link #commit()} renames over it. Closing without commit deletes the
 * temporary file, so a crash or an error never leaves a half-written target. A target
 * ending in {@code .gz} is gzip-compressed, one ending in {@code .zst} zstd-compressed. A command stopped by Ctrl-C or SIGTERM before its
 * commit calls {@link #abandonAll()} from its shutdown hook, so no temporary file is left behind
 * (not a hook of its own here: commands such as the proxy commit their logs in their hooks).
 * SIGKILL runs no hook: the next output into the same directory removes such leftovers
 * ({@link #removeStaleTemporaries}).
 *
 * <p>Only a regular file is ever replaced. A symbolic link is written through: the file it
 * points to is replaced and the link stays. A FIFO or a character device ({@code /dev/stdout},
 * {@code /dev/null}) is written through as a stream, without a temporary file, since it cannot be
 * replaced; anything else (a block device, a socket) is refused. Write errors name the target and
 * the reason (disk full, permission denied).
 */
public final class AtomicOutput implements AutoCloseable {
    private final Path target;
    /** Null when the target is a FIFO or a character device, written through. */
    private final Path temporary;
    private final OutputStream file;
    private final OutputStream stream;
    private boolean closed;

    /** Temporary files not yet committed or abandoned: what the shutdown hook deletes. */
    private static final Set<Path> OPEN = ConcurrentHashMap.newKeySet();
    /** Set by {@link #abandonAll()}, under {@code OPEN}'s lock: the process is stopping, no output opens. */
    private static boolean stopping;
    private static final long PID = ProcessHandle.current().pid();
    /** {@code .<target>.<pid>-<random>.tmp}: this class's temporary files and nobody else's. */
    private static final Pattern TEMPORARY = Pattern.compile("\\..+\\.([0-9]{1,19})-[0-9a-z]{1,13}\\.tmp");
    /**
     * A temporary file untouched this long is stale even if a process of its PID is alive (PIDs
     * are reused); a live writer touches its file far more often.
     */
    static final Duration STALE_AFTER = Duration.ofHours(6);
    /** Directories already cleaned by this process: once is enough, and output directories may be large. */
    private static final Set<Path> CLEANED = ConcurrentHashMap.newKeySet();

    private AtomicOutput(Path requested) throws IOException {
        this.target = Targets.followLinks(requested.toAbsolutePath());
        Path directory = this.target.getParent();
        Targets.Kind kind = Targets.kind(this.target);
        if (kind == Targets.Kind.DIRECTORY) {
            throw new IOException(requested + ": is a directory, not a file to write");
        }
        if (kind == Targets.Kind.OTHER) {
            throw new IOException(requested + ": is not a regular file, a FIFO or a character device"
                    + " (a block device or a socket): refused; name a regular file to write");
        }
        OutputStream out;
        if (kind == Targets.Kind.STREAM) {
            // nothing to rename over a FIFO or a device: write through, without atomicity
            this.temporary = null;
            try {
                out = new BufferedOutputStream(Files.newOutputStream(this.target, StandardOpenOption.WRITE), 1 << 16);
            } catch (IOException e) {
                throw new IOException(requested + ": cannot write: " + IoErrors.reason(e), e);
            }
        } else {
            try {
                Files.createDirectories(directory);
            } catch (FileAlreadyExistsException e) {
                throw new IOException(requested + ": cannot write: " + e.getFile() + " is a file, not a directory", e);
            } catch (IOException e) {
                throw new IOException(requested + ": cannot create its directory " + directory + ": " + IoErrors.reason(e), e);
            }
            removeStaleTemporaries(directory);
            // Not Files.createTempFile: its owner-only permissions would carry over to the target.
            // The name carries the writer's PID, so a later writer can tell a dead writer's leftover.
            this.temporary = directory.resolve("." + this.target.getFileName() + "." + PID + "-" + Long.toUnsignedString(
                    ThreadLocalRandom.current().nextLong(), 36) + ".tmp");
            // created and registered at once, and not after abandonAll: the command's own threads run on
            // while the shutdown hooks do, and a file opened behind the hook's back would stay
            synchronized (OPEN) {
                if (stopping) {
                    throw new IOException(requested + ": not written: the command is stopping");
                }
                try {
                    out = new BufferedOutputStream(Files.newOutputStream(temporary, StandardOpenOption.CREATE_NEW),
                            1 << 16);
                } catch (IOException e) {
                    // the temporary file's name means nothing to the user: name the target and the reason
                    throw new IOException(requested + ": cannot write in " + directory + ": " + IoErrors.reason(e), e);
                }
                OPEN.add(temporary);
            }
        }
        OutputStream named = new NamedErrors(out, requested);
        this.file = compressing(requested.getFileName().toString(), named);
        // Writers wrapping the stream may close it; only commit() or close() may end the file.
        this.stream = new FilterOutputStream(file) {
            @Override
            public void write(byte[] bytes, int offset, int length) throws IOException {
                this.out.write(bytes, offset, length); // not FilterOutputStream's byte-by-byte loop
            }

            @Override
            public void close() throws IOException {
                flush();
            }
        };
    }

    /** Level 1: on scene JSON about a tenth of gzip's CPU at its default level, the size within 13 % (docs/scale.md). */
    static final int ZSTD_LEVEL = 1;

    /** A name ending in {@code .gz} is written gzip-compressed, {@code .zst} zstd-compressed. */
    private static OutputStream compressing(String name, OutputStream out) throws IOException {
        if (name.endsWith(".gz")) {
            return new GZIPOutputStream(out, 1 << 16);
        }
        if (name.endsWith(".zst")) {
            // each write is a call into the native library: hand it large blocks
            return new BufferedOutputStream(new ZstdOutputStream(out, ZSTD_LEVEL), 1 << 16);
        }
        return out;
    }

    /** Write errors (disk full, a device refusing) name the target, not the temporary file. */
    private static final class NamedErrors extends FilterOutputStream {
        private final Path target;

        NamedErrors(OutputStream out, Path target) {
            super(out);
            this.target = target;
        }

        @Override
        public void write(int b) throws IOException {
            try {
                out.write(b);
            } catch (IOException e) {
                throw named(e);
            }
        }

        @Override
        public void write(byte[] bytes, int offset, int length) throws IOException {
            try {
                out.write(bytes, offset, length);
            } catch (IOException e) {
                throw named(e);
            }
        }

        @Override
        public void flush() throws IOException {
            try {
                out.flush();
            } catch (IOException e) {
                throw named(e);
            }
        }

        @Override
        public void close() throws IOException {
            try {
                out.close();
            } catch (IOException e) {
                throw named(e);
            }
        }

        private IOException named(IOException e) {
            String message = e.getMessage();
            return message != null && message.startsWith(target + ": ") ? e
                    : new IOException(target + ": cannot write: " + IoErrors.reason(e), e);
        }
    }

    /**
     * Deletes what writers killed by SIGKILL (which runs no code) left in {@code directory}:
     * temporary files of this class's pattern whose writer is no longer alive, or that nobody has
     * written to for {@link #STALE_AFTER}. Best effort: a file that cannot be looked at or
     * deleted stays.
     */
    static void removeStaleTemporaries(Path directory) {
        if (!CLEANED.add(directory)) {
            return;
        }
        long now = System.currentTimeMillis();
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(directory, ".*.tmp")) {
            for (Path entry : entries) {
                Matcher matcher = TEMPORARY.matcher(entry.getFileName().toString());
                if (!matcher.matches() || OPEN.contains(entry)) {
                    continue;
                }
                long pid = Long.parseLong(matcher.group(1));
                boolean alive = ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false);
                if (!alive || now - Files.getLastModifiedTime(entry).toMillis() > STALE_AFTER.toMillis()) {
                    Files.deleteIfExists(entry);
                }
            }
        } catch (IOException | NumberFormatException | DirectoryIteratorException e) {
            // leftovers stay; the output itself is unaffected
        }
    }

    /**
     * Deletes the temporary files of every output neither committed nor closed, for a shutdown hook
     * of a command whose interrupted work is abandoned; returns the targets that were not written.
     * From then on no output of this process opens (it fails, naming its target).
     */
    public static List<Path> abandonAll() {
        List<Path> abandoned = new ArrayList<>();
        synchronized (OPEN) {
            stopping = true;
        }
        for (Path temporary : List.copyOf(OPEN)) {
            try {
                Files.deleteIfExists(temporary);
                OPEN.remove(temporary);
                String name = temporary.getFileName().toString();
                // ".<target>.<pid>-<random>.tmp" back to the target's name
                String target = name.substring(1, name.lastIndexOf('.', name.length() - 5));
                abandoned.add(temporary.resolveSibling(target));
            } catch (IOException e) {
                // stopping: nothing more can be done
            }
        }
        return abandoned;
    }

    /** Lets outputs open again after {@link #abandonAll()}: for tests, which go on in the same JVM. */
    static void resumeAfterAbandon() {
        synchronized (OPEN) {
            stopping = false;
        }
    }

    public static AtomicOutput create(Path target) throws IOException {
        return new AtomicOutput(target);
    }

    /** The stream to write to; closing it only flushes. */
    public OutputStream stream() {
        return stream;
    }

    public Path target() {
        return target;
    }

    /** Finishes the file and moves it into place, replacing any previous file. */
    public void commit() throws IOException {
        if (closed) {
            throw new IllegalStateException("output " + target + " already closed");
        }
        closed = true;
        if (temporary == null) {
            stream.flush();
            file.close();
            return;
        }
        boolean moved = false;
        try {
            stream.flush();
            file.close();
            try {
                Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING);
            }
            moved = true;
        } finally {
            OPEN.remove(temporary);
            if (!moved) {
                Files.deleteIfExists(temporary);
            }
        }
    }

    /** Abandons the file unless committed: the target stays as it was. */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        if (temporary == null) {
            file.close();
            return;
        }
        try {
            file.close();
        } finally {
            Files.deleteIfExists(temporary);
            OPEN.remove(temporary);
        }
    }
}
