package org.scenes.internal.protocol;

import java.util.List;

/**
 * One message of the soccer server protocol, either direction, as {@link MessageParser} typed it.
 * Every message knows its head word; {@link #leftovers()} lists the parts the parser did not
 * recognise (empty when the message was fully understood), so new protocol versions degrade
 * gracefully instead of failing.
 */
public sealed interface Message
        permits See, SenseBody, Hear, InitRequest, ReconnectRequest, InitReply, Parameters, ServerNotice, Score,
        ChangePlayerType, PlayerCommand, Unknown {

    /** The message's first word: {@code see}, {@code dash}, {@code server_param}, ... */
    String head();

    /** Parts of the message that were not understood; empty for a fully understood message. */
    default List<String> leftovers() {
        return List.of();
    }

    /** Whether this is something a client sends to the server. */
    default boolean fromClient() {
        return false;
    }
}
