package org.scenes.internal.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/** Issue 31.3: a number of a see or a command that is not finite, or impossible, never enters a scene. */
class NonFiniteNumbersTest {
    private final MessageParser parser = new MessageParser();

    @ParameterizedTest
    @ValueSource(strings = {"nan", "NaN", "inf", "-inf", "Infinity", "1e999", "-1e400"})
    void aSeenObjectWithANonFiniteNumberMakesTheMessageMalformed(String number) {
        ProtocolException error = assertThrows(ProtocolException.class,
                () -> parser.parse("(see 3 ((g r) 30 0) ((b) " + number + " 2))"));
        assertTrue(error.getMessage().contains("(b)") && error.getMessage().contains("not a finite number"),
                error.getMessage());
        assertThrows(ProtocolException.class, () -> parser.parse("(see 3 ((b) 4 " + number + "))"));
        assertThrows(ProtocolException.class, () -> parser.parse("(see 3 ((p \"T\" 2) 4 5 0 0 " + number + " 0))"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"((b) -0.5 2)", "((b) 1e5 2)", "((b) 3 181)", "((f c) -200)", "((p \"T\" 2) 4 5 0 0 270 0)"})
    void impossibleDistancesAndDirectionsMakeTheMessageMalformed(String object) {
        assertThrows(ProtocolException.class, () -> parser.parse("(see 3 " + object + ")"));
    }

    @Test
    void theLimitsThemselvesAndOrdinaryNumbersStillParse() {
        See see = assertInstanceOf(See.class, parser.parse("(see 3 ((b) 0 -180) ((g r) 999 180) ((f c) 1.5e1 -3e0))"));
        assertEquals(3, see.objects().size());
        assertEquals(15, see.objects().get(2).distance(), 1e-12);
        assertEquals(List.of(), see.leftovers());
    }

    @Test
    void anUnknownWordIsStillALeftoverNotAnError() {
        See see = assertInstanceOf(See.class, parser.parse("(see 3 ((b) 1 2 x) ((g r) 30 0))"));
        assertEquals(1, see.objects().size());
        assertEquals(List.of("((b) 1 2 x)"), see.leftovers());
    }

    @Test
    void aSeeOfMoreObjectsThanTheServerCouldSendIsMalformed() {
        String flag = "((f c) 10 0) ";
        assertEquals(256, assertInstanceOf(See.class, parser.parse("(see 1 " + flag.repeat(256) + ")")).objects().size());
        ProtocolException error = assertThrows(ProtocolException.class, () -> parser.parse("(see 1 " + flag.repeat(257) + ")"));
        assertTrue(error.getMessage().contains("more than 256 objects"), error.getMessage());
    }

    @ParameterizedTest
    @ValueSource(strings = {"(dash 1e999)", "(turn inf)", "(kick 100 nan)", "(turn_neck -1e500)"})
    void aCommandWithANonFiniteNumberIsNotWellFormed(String text) {
        PlayerCommand command = assertInstanceOf(PlayerCommand.class, parser.parse(text));
        assertFalse(command.wellFormed(), text);
    }
}
