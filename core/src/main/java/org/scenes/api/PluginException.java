package org.scenes.api;

/** A plugin that cannot be found, loaded or configured; the message says what to do. */
public final class PluginException extends RuntimeException {
    public PluginException(String message) {
        super(message);
    }

    public PluginException(String message, Throwable cause) {
        super(message, cause);
    }
}
