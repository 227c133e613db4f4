package org.scenes.internal.validate;

/**
 * A metric or selector failed while validation matched one query: the message names the
 * query's index in the test scenes and its cycle, then the failure's own message (a script's
 * names its file and line).
 */
public final class QueryFailure extends RuntimeException {
    private final int index;

    QueryFailure(int index, int cycle, RuntimeException cause) {
        super("query scene " + index + " (cycle " + cycle + "): " + describe(cause), cause);
        this.index = index;
    }

    /** The query's index in the test scenes, from 0. */
    public int index() {
        return index;
    }

    private static String describe(RuntimeException cause) {
        String message = cause.getMessage();
        return message == null ? cause.getClass().getSimpleName() : message;
    }
}
