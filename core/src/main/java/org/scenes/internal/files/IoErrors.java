package org.scenes.internal.files;

import java.io.FileNotFoundException;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;

/** What went wrong with a file, in the words a one-line error message needs. */
public final class IoErrors {
    private IoErrors() {
    }

    /**
     * Why {@code e} happened, without the file's name: "permission denied", "Is a directory", ...
     * ({@link AccessDeniedException}'s own message is only the file's name).
     */
    public static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileSystemException fileSystem && fileSystem.getReason() != null) {
            return fileSystem.getReason();
        }
        String message = e.getMessage();
        if (message == null) {
            return e.getClass().getSimpleName();
        }
        int open = message.lastIndexOf(" (");
        if (e instanceof FileNotFoundException && open > 0 && message.endsWith(")")) {
            // java.io's "PATH (Is a directory)"
            return message.substring(open + 2, message.length() - 1);
        }
        return message;
    }
}
