package org.scenes.internal.experiment;

/** A configuration of a sweep failed; the message names the configuration, the cause says why. */
public final class ExperimentException extends RuntimeException {
    public ExperimentException(String message, Throwable cause) {
        super(message, cause);
    }
}
