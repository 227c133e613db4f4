package org.scenes.agent.net;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.scenes.internal.files.AtomicTextOutput;
import org.scenes.internal.proxylog.Direction;
import org.scenes.internal.proxylog.ProxyLogLine;

/**
 * One player's traffic in the project's proxy log format (what {@code scenes proxy} writes, what
 * {@code scenes convert} reads): every datagram either way, timed. The file appears when the
 * player stops.
 */
final class TrafficLog implements AutoCloseable {
    private final AtomicTextOutput output;
    private final Writer writer;
    private final long startNanos = System.nanoTime();

    TrafficLog(Path file) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        output = AtomicTextOutput.create(file);
        writer = output.writer();
        writer.write(ProxyLogLine.HEADER);
        writer.write('\n');
    }

    void sent(String message) throws IOException {
        line(Direction.CLIENT_TO_SERVER, message.getBytes(StandardCharsets.UTF_8));
    }

    void received(byte[] message) throws IOException {
        line(Direction.SERVER_TO_CLIENT, message);
    }

    private void line(Direction direction, byte[] message) throws IOException {
        writer.write(new ProxyLogLine((System.nanoTime() - startNanos) / 1000, direction, message).format());
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
