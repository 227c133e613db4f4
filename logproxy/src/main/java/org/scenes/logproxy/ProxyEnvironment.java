package org.scenes.logproxy;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;
import java.util.function.LongSupplier;

/**
 * What the proxy takes from its surroundings: the time its idle and end-of-game timeouts are
 * measured on, and how it opens a log file. {@link #system()} is the real thing; a test passes
 * a clock it advances itself (so a timeout elapses exactly when the test says, whatever the
 * machine's load) or files that stall or fail like a sick disk.
 *
 * @param nanoTime a monotonic clock in nanoseconds, read by the forwarding thread only
 * @param logFiles opens a new log file for writing
 */
public record ProxyEnvironment(LongSupplier nanoTime, LogFiles logFiles) {
    /** Opens the proxy's log files. */
    @FunctionalInterface
    public interface LogFiles {
        OutputStream create(Path file) throws IOException;
    }

    public ProxyEnvironment {
        Objects.requireNonNull(nanoTime, "nanoTime");
        Objects.requireNonNull(logFiles, "logFiles");
    }

    /** The system's monotonic clock and the file system. */
    public static ProxyEnvironment system() {
        return new ProxyEnvironment(System::nanoTime, Files::newOutputStream);
    }

    public ProxyEnvironment withClock(LongSupplier clock) {
        return new ProxyEnvironment(clock, logFiles);
    }

    public ProxyEnvironment withLogFiles(LogFiles files) {
        return new ProxyEnvironment(nanoTime, files);
    }
}
