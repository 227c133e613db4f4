package org.scenes.internal.gamelog;

import java.io.IOException;
import java.nio.file.Path;

/** A game log that cannot be read: the message names the file and the line. */
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
