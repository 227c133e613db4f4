package org.scenes.agent.sim;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.scenes.files.AtomicOutput;

/**
 * One player's exchange in the classic {@code .lsf} layout: every message either way, one per
 * line, in order, no time, no direction. Appears only when the game finished ({@link #commit}).
 */
final class PlayerLog implements AutoCloseable {
    private final AtomicOutput output;
    private final Writer writer;

    PlayerLog(Path file) throws IOException {
        this.output = AtomicOutput.create(file);
        this.writer = new BufferedWriter(new OutputStreamWriter(output.stream(), StandardCharsets.UTF_8), 1 << 16);
    }

    void line(String message) throws IOException {
        writer.write(message);
        writer.write('\n');
    }

    Path commit() throws IOException {
        writer.flush();
        output.commit();
        return output.target();
    }

    @Override
    public void close() throws IOException {
        output.close();
    }
}
