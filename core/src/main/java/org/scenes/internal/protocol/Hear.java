package org.scenes.internal.protocol;

/**
 * {@code (hear TIME SENDER MESSAGE)} in every form the server has used: the referee announcing a
 * play mode, the player's own {@code say}, a coach or trainer, and other players (v8+
 * {@code (hear T DIR our UNUM "msg")} / {@code (hear T DIR opp "msg")}, older {@code (hear T DIR msg)}).
 *
 * @param direction direction of a player's voice, {@code NaN} for referee, self and coach
 * @param uniformNumber speaker's uniform number when the server says it (teammates), else 0
 * @param text the play mode or message, without quotes; empty when the server withheld it
 */
public record Hear(int time, Speaker speaker, double direction, int uniformNumber, String text) implements Message {

    /** Who spoke. */
    public enum Speaker {
        REFEREE, SELF, COACH, TEAMMATE, OPPONENT,
        /** A player whose team the protocol version does not tell. */
        PLAYER
    }

    @Override
    public String head() {
        return "hear";
    }
}
