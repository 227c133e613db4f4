package org.scenes.internal.protocol;

import org.scenes.api.Side;

/**
 * The server's answer to {@code init} or {@code reconnect}: {@code (init SIDE UNUM PLAYMODE)} for a
 * player, {@code (reconnect SIDE PLAYMODE)} after a player's reconnect (uniform number 0),
 * {@code (init SIDE ok)} for an online coach and {@code (init ok)} for the trainer (no side). Coach
 * and trainer replies carry no play mode (null).
 */
public record InitReply(String head, Side side, int uniformNumber, String playMode, Role role) implements Message {

    /** Which kind of client the server accepted. */
    public enum Role { PLAYER, COACH, TRAINER }

    /** A player's reply. */
    public InitReply(String head, Side side, int uniformNumber, String playMode) {
        this(head, side, uniformNumber, playMode, Role.PLAYER);
    }
}
