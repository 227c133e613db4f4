package org.scenes.internal.gamelog;

import java.io.IOException;
import java.nio.file.Path;

/**
 * What the players sent, step by step, as a command log gives it: read from a {@code .rcl}
 * ({@link CommandLogReader}) or inferred from the game log alone.
 */
public interface CommandSource extends AutoCloseable {
    /** The next entry, a player's message or the referee's, in the order of the steps; null at the end. */
    CommandLogReader.Entry next() throws IOException;

    /** The file the entries come from, for messages naming it. */
    Path file();

    @Override
    void close() throws IOException;
}
