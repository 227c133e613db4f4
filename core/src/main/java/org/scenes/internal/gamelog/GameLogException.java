package org.scenes.internal.gamelog;

import java.io.IOException;
import java.nio.file.Path;

/**
 * A game log that cannot be read: the message names the file and the line. Two types, this and
 * convert's {@code LogException} (a player's log), because this package sits below convert and cannot
 * name its types; both are failed work on bad data to their callers (the CLI exits 1 for either).
 */
public final class GameLogException extends IOException {
    private final Path file;
    private final long line;
    private final boolean cutOff;

    GameLogException(Path file, long line, String problem) {
        this(file, line, problem, false);
    }

    GameLogException(Path file, long line, String problem, boolean cutOff) {
        super(file + ":" + line + ": " + problem);
        this.file = file;
        this.line = line;
        this.cutOff = cutOff;
    }

    /**
     * Whether the log ends inside a record (a list left open, a JSON array never closed), as the
     * log of a server stopped mid-write does; the records before it are whole.
     */
    public boolean cutOff() {
        return cutOff;
    }

    public Path file() {
        return file;
    }

    /** The line number, from 1. */
    public long line() {
        return line;
    }
}
