package org.scenes.internal.files;

import com.github.luben.zstd.ZstdInputStream;
import java.io.BufferedInputStream;
import java.io.FileInputStream;
import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.GZIPInputStream;

/**
 * Opens input files, decompressing gzip and zstd by their magic bytes whatever the file is called;
 * {@code -} is standard input, and pipes such as {@code /dev/stdin} are read as streams (never sought).
 */
public final class Inputs {
    /** The name that stands for standard input. */
    public static final String STANDARD_INPUT = "-";
    private static final int GZIP_MAGIC = 0x8b1f;
    /** A zstd frame's first four bytes, little-endian. */
    private static final int ZSTD_MAGIC = 0xFD2FB528;
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
        return decompressed(file, raw);
    }

    /**
     * {@code raw}, decompressed when its first bytes are gzip's or zstd's magic; errors of corrupt
     * data name {@code file}.
     */
    public static InputStream decompressed(Path file, InputStream raw) throws IOException {
        InputStream in = new BufferedInputStream(raw, 1 << 16);
        in.mark(4);
        int magic = 0;
        int read = 0;
        for (int b; read < 4 && (b = in.read()) >= 0; read++) {
            magic |= b << (8 * read);
        }
        in.reset();
        if (read >= 2 && (magic & 0xffff) == GZIP_MAGIC) {
            return new BufferedInputStream(new Decompressing(file, "gzip", in), 1 << 16);
        }
        if (read == 4 && magic == ZSTD_MAGIC) {
            return new BufferedInputStream(new Decompressing(file, "zstd", in), 1 << 16);
        }
        return in;
    }

    /** Gzip or zstd whose errors (corrupt data, truncated stream, bad trailer) name the file. */
    private static final class Decompressing extends FilterInputStream {
        private final Path file;
        private final String format;

        Decompressing(Path file, String format, InputStream compressed) throws IOException {
            super(decompress(file, format, compressed));
            this.file = file;
            this.format = format;
        }

        private static InputStream decompress(Path file, String format, InputStream compressed) throws IOException {
            try {
                if (format.equals("zstd")) {
                    // a stream cut short must fail, not end quietly as if complete
                    return new ZstdInputStream(compressed).setContinuous(false);
                }
                return new GZIPInputStream(compressed, 1 << 16);
            } catch (IOException e) {
                throw named(file, format, e);
            }
        }

        @Override
        public int read() throws IOException {
            try {
                return super.read();
            } catch (IOException e) {
                throw named(file, format, e);
            }
        }

        @Override
        public int read(byte[] bytes, int offset, int length) throws IOException {
            try {
                return super.read(bytes, offset, length);
            } catch (IOException e) {
                throw named(file, format, e);
            }
        }

        private static IOException named(Path file, String format, IOException e) {
            return e instanceof CorruptCompressionException ? e : new CorruptCompressionException(file, format, e);
        }
    }

    /** Gzip or zstd data that cannot be decompressed; the message names the file, {@link #reason()} does not. */
    public static final class CorruptCompressionException extends IOException {
        private final String reason;

        CorruptCompressionException(Path file, String format, IOException cause) {
            this(file, "corrupt or truncated " + format + " (" + (cause.getMessage() == null
                    ? cause.getClass().getSimpleName() : cause.getMessage()) + ")", (Throwable) cause);
        }

        private CorruptCompressionException(Path file, String reason, Throwable cause) {
            super(file + ": " + reason, cause);
            this.reason = reason;
        }

        /** What is wrong, without the file's name (for messages that name it already). */
        public String reason() {
            return reason;
        }
    }
}
