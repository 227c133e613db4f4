package org.scenes.protocol;

import org.scenes.scene.Side;

/**
 * The server's answer to {@code init}: {@code (init SIDE UNUM PLAYMODE)} for a player, or
 * {@code (reconnect SIDE PLAYMODE)} (uniform number 0) after a reconnect.
 */
public record InitReply(String head, Side side, int uniformNumber, String playMode) implements Message {
}
