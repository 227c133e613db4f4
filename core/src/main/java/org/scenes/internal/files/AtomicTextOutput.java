package org.scenes.internal.files;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * A text file written through {@link AtomicOutput}: buffered UTF-8 (gzipped when the name ends in
 * {@code .gz}), in place only once committed, so a log interrupted half way is never left behind.
 */
public final class AtomicTextOutput implements AutoCloseable {
    private final AtomicOutput output;
    private final Writer writer;

    private AtomicTextOutput(Path target) throws IOException {
        output = AtomicOutput.create(target);
        writer = new BufferedWriter(new OutputStreamWriter(output.stream(), StandardCharsets.UTF_8), 1 << 16);
    }

    public static AtomicTextOutput create(Path target) throws IOException {
        return new AtomicTextOutput(target);
    }

    public Writer writer() {
        return writer;
    }

    /** Flushes what was written and moves the file into place; returns where it is. */
    public Path commit() throws IOException {
        writer.flush();
        output.commit();
        return output.target();
    }

    /** Abandons the file unless committed. */
    @Override
    public void close() throws IOException {
        output.close();
    }
}
