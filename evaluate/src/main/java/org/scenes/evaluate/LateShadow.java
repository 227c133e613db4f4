package org.scenes.evaluate;

import java.util.function.Consumer;

/**
 * A shadow whose commands come on their own time, not within the call that gave it a message (a
 * program over UDP on a real-time server). Whoever numbers the sees a shadow answers calls
 * {@link #collect} before it counts the next message, so that what came in between is the reply to
 * the see before.
 */
interface LateShadow {
    /** Hands the commands that came since the last call to {@code send}, in the order they came. */
    void collect(Consumer<String> send);
}
