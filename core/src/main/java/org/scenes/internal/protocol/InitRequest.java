package org.scenes.internal.protocol;

/**
 * The client's {@code (init TEAM [(version V)] [(goalie)])}; version 3 when none is sent. The
 * trainer's {@code (init (version V))} names no team (null).
 */
public record InitRequest(String team, double version, boolean goalie) implements Message {
    @Override
    public String head() {
        return "init";
    }

    @Override
    public boolean fromClient() {
        return true;
    }
}
