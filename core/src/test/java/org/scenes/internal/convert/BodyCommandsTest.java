package org.scenes.internal.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.MessageParser;

/** The first body command of a sent line, as rcssserver would execute it. */
class BodyCommandsTest {
    private final MessageParser parser = new MessageParser();

    @Test
    void theFirstBodyCommandOfALine() {
        assertEquals(CommandType.DASH, BodyCommands.first(parser, "(dash 100)"));
        assertEquals(CommandType.DASH, BodyCommands.first(parser, "(turn_neck 10)(dash 50)(turn 30)"));
        assertEquals(CommandType.MOVE, BodyCommands.first(parser, "(move -10 0)"));
        assertEquals(CommandType.TACKLE, BodyCommands.first(parser, "(change_view wide high) (tackle 50)"));
    }

    @Test
    void noBodyCommandInOtherCommandsOrQuotedText() {
        assertNull(BodyCommands.first(parser, "(turn_neck 30)"));
        assertNull(BodyCommands.first(parser, "(change_view narrow high)(done)"));
        assertNull(BodyCommands.first(parser, "(say \"(dash 100)\")"));
    }

    @Test
    void illFormedOrAfterAMalformedCommandIsNotExecuted() {
        assertNull(BodyCommands.first(parser, "(dash)"));
        assertEquals(CommandType.TURN, BodyCommands.first(parser, "(turn 30)(foo"));
        assertNull(BodyCommands.first(parser, "(turn_neck 0)(foo(dash 100)"));
    }
}
