package org.scenes.logproxy;

/** The soccer server's three client ports; each kind is proxied the same way. */
public enum ClientKind {
    /** Players, server port 6000 by default. */
    PLAYER(0),
    /** The offline coach (trainer), server port 6001 by default. */
    COACH(1),
    /** The online coach of a team, server port 6002 by default. */
    ONLINE_COACH(2);

    private final int portOffset;

    ClientKind(int portOffset) {
        this.portOffset = portOffset;
    }

    /** Distance of this kind's default server port from the player port. */
    public int portOffset() {
        return portOffset;
    }
}
