package org.scenes.internal.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.scenes.api.Action;
import org.scenes.api.ActionType;

/** Datagrams holding several commands (librcsc sends a cycle's commands in one) and rcssserver 19's commands. */
class DatagramParsingTest {
    private final MessageParser parser = new MessageParser();

    private static List<CommandType> types(List<Message> messages) {
        return messages.stream().map(m -> ((PlayerCommand) m).type()).toList();
    }

    @Test
    void aDatagramIsSplitIntoItsMessagesTexts() {
        assertEquals(List.of("(turn 0)", "(turn_neck 0)", "(done)"), parser.texts("(turn 0)(turn_neck 0)(done)"));
        assertEquals(List.of("(dash 76 60)", "(say \"a (b) c\")"), parser.texts(" (dash 76 60) (say \"a (b) c\")\0\0"));
        assertEquals(List.of("(dash 10)"), parser.texts("(dash 10)(turn 3"), "up to a malformed one");
        assertEquals(List.of(), parser.texts(""));
    }

    @Test
    void aCyclesCommandsInOneDatagramAreParsedInOrder() {
        List<Message> messages = parser.parseAll("(turn 0)(turn_neck 0)(done)");
        assertEquals(List.of(CommandType.TURN, CommandType.TURN_NECK, CommandType.DONE), types(messages));
        List<Message> spaced = parser.parseAll(" (dash 76.345 60) (turn_neck -12)(attentionto our 7)(say \"a (b) c\")\0\0");
        assertEquals(List.of(CommandType.DASH, CommandType.TURN_NECK, CommandType.ATTENTIONTO, CommandType.SAY),
                types(spaced));
        PlayerCommand dash = (PlayerCommand) spaced.get(0);
        assertEquals(76.345, dash.first());
        assertEquals(60, dash.second());
        assertEquals("a (b) c", ((PlayerCommand) spaced.get(3)).text());
    }

    @Test
    void aSingleMessageParsesAsOneAndParseStillRejectsSeveral() {
        assertEquals(1, parser.parseAll("(see 12 ((b) 1 2))").size());
        ProtocolException error = assertThrows(ProtocolException.class, () -> parser.parse("(turn 0)(done)"));
        assertTrue(error.getMessage().contains("parseAll"), error.getMessage());
    }

    @Test
    void messagesBeforeAMalformedOneAreDeliveredAndTheColumnCountsFromTheLine() {
        byte[] line = "(turn 10)(turn_neck 5)(dash 1".getBytes(StandardCharsets.UTF_8);
        List<Message> delivered = new ArrayList<>();
        ProtocolException error = assertThrows(ProtocolException.class,
                () -> parser.parseAll(line, 0, line.length, delivered::add));
        assertEquals(List.of(CommandType.TURN, CommandType.TURN_NECK), types(delivered));
        assertTrue(error.getMessage().contains("unclosed"), error.getMessage());
        assertTrue(error.column() > 23, "column " + error.column() + " points into the third message");
        ProtocolException junk = assertThrows(ProtocolException.class, () -> parser.parseAll("(turn 0) junk"));
        assertEquals(10, junk.column());
        assertThrows(ProtocolException.class, () -> parser.parseAll("  "));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "(dash (l 100 0) (r 80 10))|90|5|(l 100 0) (r 80 10)",
        "(dash (r 80 10) (l 100 0))|90|5|(r 80 10) (l 100 0)",
        "(dash ( l  50.5 -20 ))|50.5|-20|(l 50.5 -20)",
    })
    void twoLegDash(String text, double power, double direction, String legs) {
        PlayerCommand dash = assertInstanceOf(PlayerCommand.class, parser.parse(text));
        assertTrue(dash.wellFormed());
        assertEquals(CommandType.DASH, dash.type());
        assertEquals(power, dash.first());
        assertEquals(direction, dash.second());
        assertEquals(legs, dash.text());
        assertEquals(Action.dash(power, direction), dash.toAction());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "(dash (l 100 0) (l 80 10))", "(dash (x 100 0))", "(dash (l 100))", "(dash (l 100 0 3))",
        "(dash (l 100 0) 5)", "(dash (l a 0))", "(tackle 30 maybe)", "(long_kick 100)",
    })
    void illFormedModernCommands(String text) {
        PlayerCommand command = assertInstanceOf(PlayerCommand.class, parser.parse(text));
        assertFalse(command.wellFormed());
        assertNull(command.toAction());
    }

    @Test
    void tackleKeepsItsFoulFlag() {
        assertEquals(Action.tackle(30, true), ((PlayerCommand) parser.parse("(tackle 30 on)")).toAction());
        assertEquals(Action.tackle(-45, false), ((PlayerCommand) parser.parse("(tackle -45 false)")).toAction());
        Action plain = ((PlayerCommand) parser.parse("(tackle 30)")).toAction();
        assertEquals(Action.tackle(30), plain);
        assertTrue(Double.isNaN(plain.second()));
        assertEquals("(tackle 30 on)", Action.tackle(30, true).command());
        assertEquals("(tackle 30 off)", Action.tackle(30, false).command());
        assertEquals("(tackle 30)", plain.command());
    }

    @Test
    void longKickIsACommandButNotASceneAction() {
        PlayerCommand kick = assertInstanceOf(PlayerCommand.class, parser.parse("(long_kick 100 -30)"));
        assertEquals(CommandType.LONG_KICK, kick.type());
        assertTrue(kick.wellFormed());
        assertEquals(100, kick.first());
        assertEquals(ActionType.NONE, kick.type().action());
        assertNull(kick.toAction());
    }
}
