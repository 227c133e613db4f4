package org.scenes.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import org.scenes.internal.files.Targets;

/**
 * Checks, before any work starts, that an output option names a place that can be written: a
 * search or a validation that runs for minutes must not fail at its very end on a bad path.
 */
final class OutputPaths {
    private OutputPaths() {
    }

    /** A file the command will write (its directories may still be missing). */
    static void checkFile(String option, Path target) {
        Targets.Kind kind;
        try {
            kind = Targets.kind(Targets.followLinks(target.toAbsolutePath()));
        } catch (IOException e) {
            throw new UsageException(option + " " + target + ": " + e.getMessage());
        }
        if (kind == Targets.Kind.DIRECTORY) {
            throw new UsageException(option + " " + target + ": is a directory, not a file to write");
        }
        if (kind == Targets.Kind.OTHER) {
            throw new UsageException(option + " " + target + ": is not a regular file, a FIFO or a character device;"
                    + " name a regular file to write");
        }
        checkAncestor(option, target, target.toAbsolutePath().getParent());
    }

    /**
     * A file the command will write that must not be one of its {@code inputs}: the same file by
     * identity (a link, a hard link, {@code ./x} and {@code x}) would be destroyed by the output.
     */
    static void checkFile(String option, Path target, Collection<Path> inputs) {
        checkFile(option, target);
        checkNotInput(option, target, inputs);
    }

    /** Refuses an output that is one of the inputs, before any work. */
    static void checkNotInput(String option, Path target, Collection<Path> inputs) {
        Targets.sameFileAsInput(target, inputs).ifPresent(input -> {
            throw new UsageException(option + " " + target + ": is the input " + input
                    + " (the same file); writing it would destroy the input: name another output");
        });
    }

    /** Inputs of several options as one list. */
    @SafeVarargs
    static List<Path> inputs(Collection<Path>... groups) {
        return Arrays.stream(groups).flatMap(Collection::stream).toList();
    }

    /** A file whose name must end in one of {@code extensions} (lower case, with the dot). */
    static void checkFile(String option, Path target, Collection<Path> inputs, String... extensions) {
        String name = target.getFileName().toString().toLowerCase(Locale.ROOT);
        boolean known = false;
        for (String extension : extensions) {
            known |= name.endsWith(extension);
        }
        if (!known) {
            throw new UsageException(option + " " + target + ": the name must end in " + String.join(" or ", extensions));
        }
        checkFile(option, target, inputs);
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
