package org.scenes.internal.convert;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.protocol.ProtocolException;

/**
 * The body commands in a line a player sent (dash, turn, kick, catch, tackle, move: the ones
 * rcssserver executes at most once a cycle), read with the protocol's one parser: a quoted
 * {@code say} that spells a command is no command, and an ill-formed one is not executed.
 */
public final class BodyCommands {
    private BodyCommands() {
    }

    /**
     * The type of the first well-formed body command of the line, or null for none. As the server
     * does, the commands before a malformed one count and the rest do not.
     */
    public static CommandType first(MessageParser parser, String line) {
        List<Message> messages = new ArrayList<>(4);
        byte[] bytes = line.getBytes(StandardCharsets.UTF_8);
        try {
            parser.parseAll(bytes, 0, bytes.length, messages::add);
        } catch (ProtocolException malformed) {
            // the messages before the malformed one were delivered
        }
        for (Message message : messages) {
            if (message instanceof PlayerCommand command && command.wellFormed() && command.type().body()) {
                return command.type();
            }
        }
        return null;
    }
}
