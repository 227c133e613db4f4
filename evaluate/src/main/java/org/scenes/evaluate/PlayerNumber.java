package org.scenes.evaluate;

import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.MessageParser;

/** The server's answer that gives a player its side and uniform number. */
final class PlayerNumber {
    private PlayerNumber() {
    }

    /** {@code message} as the server's answer to an init or reconnect, with a side; null for any other. */
    static InitReply given(MessageParser parser, String message) {
        if (!message.startsWith("(init ") && !message.startsWith("(reconnect ")) {
            return null;
        }
        return parser.parse(message) instanceof InitReply reply && reply.side() != null ? reply : null;
    }
}
