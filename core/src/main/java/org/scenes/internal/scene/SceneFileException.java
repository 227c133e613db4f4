package org.scenes.internal.scene;

import java.nio.file.Path;

/** A scene file that cannot be read, with the place in the file where reading stopped. */
public final class SceneFileException extends RuntimeException {
    private final transient Path file;
    private final long line;
    private final long column;

    public SceneFileException(Path file, long line, long column, String message, Throwable cause) {
        super(file + (line > 0 ? ":" + line + ":" + column : "") + ": " + message, cause);
        this.file = file;
        this.line = line;
        this.column = column;
    }

    public Path file() {
        return file;
    }

    /** 1-based line, 0 when the error has no place (e.g. the file is missing). */
    public long line() {
        return line;
    }

    public long column() {
        return column;
    }
}
