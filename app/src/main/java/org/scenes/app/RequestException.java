package org.scenes.app;

/**
 * A request a service refuses before its work, the message naming the option to change: a usage
 * error (exit 2) to the commands, where other exceptions are failed work (exit 1). Still an
 * {@link IllegalArgumentException}, so callers that catch that go on catching this.
 */
public final class RequestException extends IllegalArgumentException {
    public RequestException(String message) {
        super(message);
    }
}
