package org.scenes.simulator;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import org.scenes.internal.files.AtomicTextOutput;

/**
 * One player's exchange in the classic {@code .lsf} layout: every message either way, one per
 * line, in order, no time, no direction. Appears only when the game finished ({@link #commit}).
 */
final class PlayerLog implements AutoCloseable {
    private final AtomicTextOutput output;
    private final Writer writer;

    PlayerLog(Path file) throws IOException {
        this.output = AtomicTextOutput.create(file);
        this.writer = output.writer();
    }

    void line(String message) throws IOException {
        writer.write(message);
        writer.write('\n');
    }

    Path commit() throws IOException {
        return output.commit();
    }

    @Override
    public void close() throws IOException {
        output.close();
    }
}
