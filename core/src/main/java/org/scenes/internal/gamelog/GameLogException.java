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

    GameLogException(Path file, long line, String problem) {
        super(file + ":" + line + ": " + problem);
        this.file = file;
        this.line = line;
    }

    public Path file() {
        return file;
    }

    /** The line number, from 1. */
    public long line() {
        return line;
    }
}
