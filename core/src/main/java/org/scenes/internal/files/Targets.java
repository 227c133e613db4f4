package org.scenes.internal.files;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Collection;
import java.util.Optional;

/** What an output path is before anything is written to it, and whether it is one of the inputs. */
public final class Targets {
    /** Symbolic links followed at most, as the kernel's limit. */
    private static final int MAX_LINKS = 40;
    private static final int TYPE_BITS = 0170000;
    private static final int FIFO = 0010000;
    private static final int CHARACTER_DEVICE = 0020000;

    /** What is at an output path. */
    public enum Kind {
        /** Nothing yet: a new regular file. */
        MISSING,
        /** A regular file, replaced atomically. */
        REGULAR,
        /** A FIFO or a character device, written through as a stream. */
        STREAM,
        /** A directory. */
        DIRECTORY,
        /** A block device or a socket: never written. */
        OTHER
    }

    private Targets() {
    }

    /** The path a chain of symbolic links at {@code path} ends in (itself when it is no link). */
    public static Path followLinks(Path path) throws IOException {
        Path current = path;
        for (int links = 0; Files.isSymbolicLink(current); links++) {
            if (links == MAX_LINKS) {
                throw new IOException(path + ": too many levels of symbolic links");
            }
            Path parent = current.toAbsolutePath().getParent();
            current = parent.resolve(Files.readSymbolicLink(current)).normalize();
        }
        return current;
    }

    /** What is at {@code path}, links followed. */
    public static Kind kind(Path path) throws IOException {
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(path, BasicFileAttributes.class);
        } catch (IOException e) {
            return Kind.MISSING; // nothing there, or its directory is missing or a file: the writer says which
        }
        if (attributes.isRegularFile()) {
            return Kind.REGULAR;
        }
        if (attributes.isDirectory()) {
            return Kind.DIRECTORY;
        }
        int type = unixMode(path).orElse(0) & TYPE_BITS;
        return type == FIFO || type == CHARACTER_DEVICE ? Kind.STREAM : Kind.OTHER;
    }

    private static Optional<Integer> unixMode(Path path) {
        try {
            return Optional.of((Integer) Files.getAttribute(path, "unix:mode"));
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException e) {
            return Optional.empty(); // no unix view: the kind stays unknown, so the path is refused
        }
    }

    /**
     * The input among {@code inputs} that {@code output} is the same file as (by identity: links,
     * hard links and other spellings of one path are one file), if any. Inputs that do not exist or
     * cannot be looked at are passed over: their readers report them.
     */
    public static Optional<Path> sameFileAsInput(Path output, Collection<Path> inputs) {
        if (!Files.exists(output)) {
            return Optional.empty();
        }
        for (Path input : inputs) {
            if (Inputs.isStandardInput(input) || !Files.exists(input, LinkOption.NOFOLLOW_LINKS)) {
                continue;
            }
            try {
                if (Files.isSameFile(output, input)) {
                    return Optional.of(input);
                }
            } catch (IOException | SecurityException e) {
                // cannot tell; the input's reader says what is wrong with it
            }
        }
        return Optional.empty();
    }
}
