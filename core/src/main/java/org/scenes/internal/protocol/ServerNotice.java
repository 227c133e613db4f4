package org.scenes.internal.protocol;

/**
 * A short status message from the server: {@code (error WHAT)}, {@code (warning WHAT)},
 * {@code (ok WHAT ...)} or {@code (think)} (synchronous mode), the words after the head kept as text.
 */
public record ServerNotice(String head, String text) implements Message {
    public boolean isError() {
        return head.equals("error");
    }
}
