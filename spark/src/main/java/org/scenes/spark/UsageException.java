package org.scenes.spark;

/** A bad command line or job description: reported in one line, exit code 2. */
final class UsageException extends RuntimeException {
    UsageException(String message) {
        super(message);
    }
}
