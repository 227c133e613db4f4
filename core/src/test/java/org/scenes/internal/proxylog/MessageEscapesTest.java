package org.scenes.internal.proxylog;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Random;
import org.junit.jupiter.api.Test;

class MessageEscapesTest {
    private static byte[] bytes(int... values) {
        byte[] out = new byte[values.length];
        for (int i = 0; i < values.length; i++) {
            out[i] = (byte) values[i];
        }
        return out;
    }

    @Test
    void protocolMessagesAreUnchanged() {
        String see = "(see 12 ((f c) 12.6 6 -0 0) ((p \"Carleton\" 3) 10.5 -20 0 0 45 45))";
        assertEquals(see, MessageEscapes.escape(see.getBytes(StandardCharsets.UTF_8)));
    }

    @Test
    void namedEscapes() {
        assertEquals("a\\\\b\\nc\\rd\\te\\0f", MessageEscapes.escape("a\\b\nc\rd\te\0f".getBytes(StandardCharsets.UTF_8)));
    }

    @Test
    void otherControlBytesAndInvalidUtf8AreHex() {
        assertEquals("\\x01\\x1F\\x7F", MessageEscapes.escape(bytes(0x01, 0x1F, 0x7F)));
        // lone continuation, overlong, surrogate, above U+10FFFF, truncated sequence
        assertEquals("\\x80", MessageEscapes.escape(bytes(0x80)));
        assertEquals("\\xC0\\xAF", MessageEscapes.escape(bytes(0xC0, 0xAF)));
        assertEquals("\\xED\\xA0\\x80", MessageEscapes.escape(bytes(0xED, 0xA0, 0x80)));
        assertEquals("\\xF4\\x90\\x80\\x80", MessageEscapes.escape(bytes(0xF4, 0x90, 0x80, 0x80)));
        assertEquals("(\\xE2\\x82", MessageEscapes.escape(bytes('(', 0xE2, 0x82)));
    }

    @Test
    void wellFormedNonAsciiIsKept() {
        String text = "été € 𝄞";
        assertEquals(text, MessageEscapes.escape(text.getBytes(StandardCharsets.UTF_8)));
    }

    @Test
    void emptyMessage() {
        assertEquals("", MessageEscapes.escape(new byte[0]));
        assertArrayEquals(new byte[0], MessageEscapes.unescape(""));
    }

    @Test
    void roundTripOnArbitraryBytes() {
        Random random = new Random(20261123L);
        for (int round = 0; round < 20_000; round++) {
            byte[] original = new byte[random.nextInt(64)];
            // Mix uniform bytes with bytes biased towards UTF-8 lead/continuation ranges.
            for (int i = 0; i < original.length; i++) {
                original[i] = (byte) (random.nextBoolean() ? random.nextInt(256) : 0x80 + random.nextInt(0x78));
            }
            String escaped = MessageEscapes.escape(original);
            assertArrayEquals(original, MessageEscapes.unescape(escaped), escaped);
            assertOneValidLine(escaped);
        }
    }

    @Test
    void roundTripOnEveryShortSequence() {
        for (int first = 0; first < 256; first++) {
            for (int second = 0; second < 256; second++) {
                byte[] original = bytes(first, second, 0xA9);
                String escaped = MessageEscapes.escape(original);
                assertArrayEquals(original, MessageEscapes.unescape(escaped), escaped);
            }
        }
    }

    private static void assertOneValidLine(String escaped) {
        assertFalse(escaped.contains("\n") || escaped.contains("\r") || escaped.contains("\0"), escaped);
        byte[] encoded = escaped.getBytes(StandardCharsets.UTF_8);
        try {
            StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(encoded));
        } catch (CharacterCodingException e) {
            throw new AssertionError("escaped text is not valid UTF-8: " + escaped, e);
        }
        for (char c : escaped.toCharArray()) {
            assertTrue(c >= 0x20 && c != 0x7F, "control character in " + escaped);
        }
    }

    @Test
    void escapingIntoBytesWritesTheSameUtf8AtTheGivenOffset() {
        Random random = new Random(7);
        for (int round = 0; round < 2000; round++) {
            byte[] original = new byte[random.nextInt(40)];
            random.nextBytes(original);
            byte[] target = new byte[3 + MessageEscapes.maxEscapedLength(original.length)];
            int end = MessageEscapes.escape(original, 0, original.length, target, 3);
            assertArrayEquals(MessageEscapes.escape(original).getBytes(StandardCharsets.UTF_8),
                    java.util.Arrays.copyOfRange(target, 3, end));
        }
    }

    @Test
    void unescapeAcceptsLowerCaseHex() {
        assertArrayEquals(bytes(0xAB, 'x'), MessageEscapes.unescape("\\xabx"));
    }

    @Test
    void badEscapesNameTheColumn() {
        IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class,
                () -> MessageEscapes.unescape("(say \\q)"));
        assertEquals("column 6: unknown escape \\q", unknown.getMessage());
        assertThrows(IllegalArgumentException.class, () -> MessageEscapes.unescape("abc\\"));
        assertThrows(IllegalArgumentException.class, () -> MessageEscapes.unescape("\\x4"));
        assertThrows(IllegalArgumentException.class, () -> MessageEscapes.unescape("\\xZZ"));
    }
}
