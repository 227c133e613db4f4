package org.scenes.convert;

import java.nio.file.Path;

/** A log line that could not be parsed; conversion goes on without it unless strict. */
public record MalformedLine(Path file, long line, String problem) {
    /** {@code file:line: problem}, the form warnings are printed in. */
    public String describe() {
        return file + ":" + line + ": " + problem;
    }
}
