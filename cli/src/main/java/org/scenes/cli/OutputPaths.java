package org.scenes.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Checks, before any work starts, that an output option names a place that can be written: a
 * search or a validation that runs for minutes must not fail at its very end on a bad path.
 */
final class OutputPaths {
    private OutputPaths() {
    }

    /** A file the command will write (its directories may still be missing). */
    static void checkFile(String option, Path target) {
        if (Files.isDirectory(target)) {
            throw new UsageException(option + " " + target + ": is a directory, not a file to write");
        }
        checkAncestor(option, target, target.toAbsolutePath().getParent());
    }

    /** A file whose name must end in one of {@code extensions} (lower case, with the dot). */
    static void checkFile(String option, Path target, String... extensions) {
        String name = target.getFileName().toString().toLowerCase(Locale.ROOT);
        boolean known = false;
        for (String extension : extensions) {
            known |= name.endsWith(extension);
        }
        if (!known) {
            throw new UsageException(option + " " + target + ": the name must end in " + String.join(" or ", extensions));
        }
        checkFile(option, target);
    }

    /** A directory the command will write files into (created when missing). */
    static void checkDirectory(String option, Path directory) {
        if (Files.exists(directory) && !Files.isDirectory(directory)) {
            throw new UsageException(option + " " + directory + ": is a file, not a directory");
        }
        checkAncestor(option, directory, directory.toAbsolutePath());
    }

    /** The nearest existing directory at or above {@code directory} must be a writable directory. */
    private static void checkAncestor(String option, Path target, Path directory) {
        Path existing = directory;
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null) {
            return;
        }
        if (!Files.isDirectory(existing)) {
            throw new UsageException(option + " " + target + ": " + existing + " is a file, not a directory");
        }
        if (!Files.isWritable(existing)) {
            throw new UsageException(option + " " + target + ": cannot write in " + existing + ": permission denied");
        }
    }
}
