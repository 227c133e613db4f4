package org.scenes.internal.convert;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.scenes.internal.proxylog.MessageEscapes;

/** A log line that could not be parsed; conversion goes on without it unless strict. */
public record MalformedLine(Path file, long line, String problem) {
    /** {@code file:line: problem}, the form warnings are printed in. */
    public String describe() {
        return file + ":" + line + ": " + escaped(problem);
    }

    /** Text with control bytes shown as escapes ({@code \0}, {@code \x1B}), safe to print on a terminal. */
    static String escaped(String text) {
        return MessageEscapes.escape(text.getBytes(StandardCharsets.UTF_8));
    }
}
