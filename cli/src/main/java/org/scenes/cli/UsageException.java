package org.scenes.cli;

/** A bad command line discovered after parsing (e.g. an unknown plugin name): exit code 2. */
final class UsageException extends RuntimeException {
    UsageException(String message) {
        super(message);
    }
}
