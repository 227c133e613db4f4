package org.scenes.files;

import java.io.BufferedOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.zip.GZIPOutputStream;

/**
 * An output file that appears only when complete: bytes go to a temporary file beside the
 * target, which {@link #commit()} renames over it. Closing without commit deletes the
 * temporary file, so a crash or an error never leaves a half-written target. A target
 * ending in {@code .gz} is gzip-compressed.
 */
public final class AtomicOutput implements AutoCloseable {
    private final Path target;
    private final Path temporary;
    private final OutputStream file;
    private final OutputStream stream;
    private boolean closed;

    private AtomicOutput(Path target) throws IOException {
        this.target = target.toAbsolutePath();
        Path directory = this.target.getParent();
        Files.createDirectories(directory);
        // Not Files.createTempFile: its owner-only permissions would carry over to the target.
        this.temporary = directory.resolve("." + this.target.getFileName() + "." + Long.toUnsignedString(
                java.util.concurrent.ThreadLocalRandom.current().nextLong(), 36) + ".tmp");
        OutputStream out = new BufferedOutputStream(
                Files.newOutputStream(temporary, java.nio.file.StandardOpenOption.CREATE_NEW), 1 << 16);
        this.file = target.getFileName().toString().endsWith(".gz") ? new GZIPOutputStream(out, 1 << 16) : out;
        // Writers wrapping the stream may close it; only commit() or close() may end the file.
        this.stream = new FilterOutputStream(file) {
            @Override
            public void write(byte[] bytes, int offset, int length) throws IOException {
                out.write(bytes, offset, length);
            }

            @Override
            public void close() throws IOException {
                flush();
            }
        };
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
        try {
            file.close();
        } finally {
            Files.deleteIfExists(temporary);
        }
    }
}
