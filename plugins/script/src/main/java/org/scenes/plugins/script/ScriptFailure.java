package org.scenes.plugins.script;

/**
 * An exception thrown by a script while it ran, located in the script: {@code file:line}
 * of the innermost script frame, what went wrong, and what the script was working on.
 * Callers that know more (the validation loop knows the query's index) add it to the
 * message; the cause keeps the script's own exception and stack trace.
 */
public final class ScriptFailure extends RuntimeException {
    private final String script;
    private final int line;

    ScriptFailure(String script, int line, String context, Throwable cause) {
        super(script + (line > 0 ? ":" + line : "") + ": " + describe(cause) + (context.isEmpty() ? "" : " (" + context + ")"),
                cause);
        this.script = script;
        this.line = line;
    }

    /** The script's path as the user wrote it. */
    public String script() {
        return script;
    }

    /** The script line that failed, 0 when the failure did not come from a line of the script. */
    public int line() {
        return line;
    }

    private static String describe(Throwable cause) {
        String message = cause.getMessage();
        String type = cause.getClass().getSimpleName();
        return message == null || message.isBlank() ? type : type + ": " + message.strip().replaceAll("\\s*\\R\\s*", " ");
    }

    /**
     * Wraps a throwable that escaped a script call, locating the line in the script's frames.
     *
     * @param fileName the script's file name as compiled (the stack traces' file name)
     */
    static ScriptFailure of(String script, String fileName, String context, Throwable cause) {
        int line = 0;
        for (StackTraceElement frame : cause.getStackTrace()) {
            if (fileName.equals(frame.getFileName()) && frame.getLineNumber() > 0) {
                line = frame.getLineNumber();
                break;
            }
        }
        return new ScriptFailure(script, line, context, cause);
    }
}
