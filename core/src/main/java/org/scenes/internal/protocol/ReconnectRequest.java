package org.scenes.internal.protocol;

/** The client's {@code (reconnect TEAM UNUM)}: a player taking back its seat after a disconnect. */
public record ReconnectRequest(String team, int uniformNumber) implements Message {
    @Override
    public String head() {
        return "reconnect";
    }

    @Override
    public boolean fromClient() {
        return true;
    }
}
