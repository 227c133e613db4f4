package org.scenes.internal.protocol;

/**
 * A message that is not a well-formed s-expression or whose known head is followed by something
 * of the wrong shape (e.g. {@code (see abc)}). The column is 1-based within the message.
 */
public final class ProtocolException extends RuntimeException {
    private final int column;

    public ProtocolException(int column, String message) {
        super("column " + column + ": " + message);
        this.column = column;
    }

    public int column() {
        return column;
    }
}
