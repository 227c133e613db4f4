package org.scenes.internal.convert;

import java.nio.file.Path;

/**
 * A log that cannot be read or a malformed line under {@code --strict}, naming file and line.
 * A game log's twin is {@link org.scenes.internal.gamelog.GameLogException} (see there why there are two).
 */
public final class LogException extends RuntimeException {
    private final transient Path file;
    private final long line;

    public LogException(Path file, long line, String message, Throwable cause) {
        // log text quoted in a message is escaped: raw control bytes would drive the user's terminal
        super(file + (line > 0 ? ":" + line : "") + ": " + MalformedLine.escaped(message), cause);
        this.file = file;
        this.line = line;
    }

    public Path file() {
        return file;
    }

    /** 1-based line, 0 when the problem is the whole file. */
    public long line() {
        return line;
    }
}
