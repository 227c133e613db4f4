package org.scenes.internal.protocol;

/** The server's {@code (score TIME OUR THEIR)}; the client's request is a {@link PlayerCommand}. */
public record Score(int time, int our, int their) implements Message {
    @Override
    public String head() {
        return "score";
    }
}
