package org.scenes.options;

/**
 * A bad option value, its message naming the option: a usage error (exit 2) to the commands, where
 * an {@link IllegalArgumentException} from core about the data is failed work (exit 1). Still an
 * {@code IllegalArgumentException}, so callers that catch that go on catching this.
 */
public final class OptionException extends IllegalArgumentException {
    OptionException(String message) {
        super(message);
    }

    OptionException(String message, Throwable cause) {
        super(message, cause);
    }
}
