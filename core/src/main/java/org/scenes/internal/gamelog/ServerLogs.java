package org.scenes.internal.gamelog;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import org.scenes.internal.files.Inputs;

/** Tells the server's logs apart by their content (plain or gzip), whatever they are called. */
public final class ServerLogs {
    /** The server's two logs of a game. */
    public enum Kind {
        /** A game log ({@code .rcg}): {@code ULG4} to {@code ULG6}, or rcssserver 19's JSON array. */
        GAME,
        /** A command log ({@code .rcl}): lines starting {@code TIME,STOPPAGE<TAB>}. */
        COMMAND
    }

    private static final int PEEK = 64;

    private ServerLogs() {
    }

    /** The kind of server log {@code file} is, or null when it is neither (e.g. a player's log). */
    public static Kind detect(Path file) throws IOException {
        try (InputStream in = Inputs.open(file)) {
            return detect(in);
        }
    }

    /** The kind of server log a stream (already decompressed) starts, or null; reads its first bytes. */
    public static Kind detect(InputStream in) throws IOException {
        byte[] head = new byte[PEEK];
        int length = 0;
        int read;
        while (length < PEEK && (read = in.read(head, length, PEEK - length)) > 0) {
            length += read;
        }
        int start = 0;
        while (start < length && Character.isWhitespace(head[start])) {
            start++;
        }
        if (start == length) {
            return null;
        }
        if (length - start >= 3 && head[start] == 'U' && head[start + 1] == 'L' && head[start + 2] == 'G') {
            // any version: a game log of one this build does not read is refused by its reader, naming it
            return Kind.GAME;
        }
        if (head[start] == '[') {
            return Kind.GAME;
        }
        int i = start;
        while (i < length && Character.isDigit(head[i])) {
            i++;
        }
        if (i == start || i >= length || head[i] != ',') {
            return null;
        }
        int digits = ++i;
        while (i < length && Character.isDigit(head[i])) {
            i++;
        }
        return i > digits && i < length && head[i] == '\t' ? Kind.COMMAND : null;
    }
}
