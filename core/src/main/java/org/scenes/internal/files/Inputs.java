package org.scenes.internal.files;

import java.io.BufferedInputStream;
import java.io.FileInputStream;
import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.GZIPInputStream;

/**
 * Opens input files, decompressing gzip by its magic bytes whatever the file is called; {@code -}
 * is standard input, and pipes such as {@code /dev/stdin} are read as streams (never sought).
 */
public final class Inputs {
    /** The name that stands for standard input. */
    public static final String STANDARD_INPUT = "-";
    private static final int GZIP_MAGIC = 0x8b1f;
    /** For a message when memory runs out: which input was being read, most likely. */
    private static volatile Path lastOpened;

    private Inputs() {
    }

    /** True for the path {@code -}, which {@link #open} reads from standard input. */
    public static boolean isStandardInput(Path file) {
        return file.toString().equals(STANDARD_INPUT);
    }

    /** The input opened last in this process, or null: what an out-of-memory message can name. */
    public static Path lastOpened() {
        return lastOpened;
    }

    public static InputStream open(Path file) throws IOException {
        lastOpened = file;
        InputStream raw;
        if (isStandardInput(file)) {
            raw = new FilterInputStream(System.in) {
                @Override
                public void close() {
                    // standard input belongs to the process, not to one reader
                }
            };
        } else if (Files.isRegularFile(file) || !Files.exists(file)) {
            raw = Files.newInputStream(file);
        } else {
            // a pipe or device: the NIO stream asks the channel its position to answer available(),
            // which fails on a pipe with "Illegal seek"; FileInputStream asks the kernel instead
            raw = new FileInputStream(file.toFile());
        }
        InputStream in = new BufferedInputStream(raw, 1 << 16);
        in.mark(2);
        int first = in.read();
        int second = in.read();
        in.reset();
        if (first >= 0 && second >= 0 && (first | (second << 8)) == GZIP_MAGIC) {
            return new BufferedInputStream(new NamedGzip(file, in), 1 << 16);
        }
        return in;
    }

    /** Gzip whose errors (corrupt data, truncated stream, bad trailer) name the file. */
    private static final class NamedGzip extends FilterInputStream {
        private final Path file;

        NamedGzip(Path file, InputStream compressed) throws IOException {
            super(gzip(file, compressed));
            this.file = file;
        }

        private static InputStream gzip(Path file, InputStream compressed) throws IOException {
            try {
                return new GZIPInputStream(compressed, 1 << 16);
            } catch (IOException e) {
                throw named(file, e);
            }
        }

        @Override
        public int read() throws IOException {
            try {
                return super.read();
            } catch (IOException e) {
                throw named(file, e);
            }
        }

        @Override
        public int read(byte[] bytes, int offset, int length) throws IOException {
            try {
                return super.read(bytes, offset, length);
            } catch (IOException e) {
                throw named(file, e);
            }
        }

        private static IOException named(Path file, IOException e) {
            return e instanceof CorruptGzipException ? e : new CorruptGzipException(file, e);
        }
    }

    /** Gzip data that cannot be decompressed; the message names the file, {@link #reason()} does not. */
    public static final class CorruptGzipException extends IOException {
        private final String reason;

        CorruptGzipException(Path file, IOException cause) {
            this(file, "corrupt or truncated gzip (" + (cause.getMessage() == null
                    ? cause.getClass().getSimpleName() : cause.getMessage()) + ")", cause);
        }

        private CorruptGzipException(Path file, String reason, IOException cause) {
            super(file + ": " + reason, cause);
            this.reason = reason;
        }

        /** What is wrong, without the file's name (for messages that name it already). */
        public String reason() {
            return reason;
        }
    }
}
