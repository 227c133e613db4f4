package org.scenes.api;

/** A plugin that cannot be found, loaded or configured; the message says what to do. */
public final class PluginException extends RuntimeException {
    /** @param message one line naming the plugin and what to do */
    public PluginException(String message) {
        super(message);
    }

    /**
     * @param message one line naming the plugin and what to do
     * @param cause the failure underneath
     */
    public PluginException(String message, Throwable cause) {
        super(message, cause);
    }
}
