package org.scenes.internal.proxylog;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class ProxyLogLineTest {
    @Test
    void formatsAndParsesBack() {
        ProxyLogLine line = new ProxyLogLine(3_000_042L, Direction.SERVER_TO_CLIENT,
                "(hear 0 referee \"a\nb\")\0x".getBytes(StandardCharsets.UTF_8));
        assertEquals("3.000042 s2c (hear 0 referee \"a\\nb\")\\0x", line.format());
        assertEquals(line, ProxyLogLine.parse(line.format()));
    }

    @Test
    void emptyMessageWithOrWithoutTrailingSpace() {
        assertArrayEquals(new byte[0], ProxyLogLine.parse("0.000001 c2s ").message());
        assertArrayEquals(new byte[0], ProxyLogLine.parse("0.000001 c2s").message());
        assertEquals("0.000001 c2s ", new ProxyLogLine(1, Direction.CLIENT_TO_SERVER, new byte[0]).format());
    }

    @Test
    void messagesKeepTheirSpaces() {
        assertEquals(" (dash 100) ", ProxyLogLine.parse("12.500000 c2s  (dash 100) ").text());
    }

    @Test
    void malformedLinesAreRejectedWithColumn() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ProxyLogLine.parse("12.5 c2s (dash 1)"))
                .getMessage().startsWith("column 1:"));
        assertEquals("column 10: expected c2s or s2c, found 'up'",
                assertThrows(IllegalArgumentException.class, () -> ProxyLogLine.parse("1.000000 up (x)")).getMessage());
        assertEquals("column 16: unknown escape \\q",
                assertThrows(IllegalArgumentException.class, () -> ProxyLogLine.parse("1.000000 c2s (a\\q)")).getMessage());
    }

    @Test
    void headerAndComments() {
        assertTrue(ProxyLogLine.isComment(ProxyLogLine.HEADER));
        assertTrue(ProxyLogLine.isComment("# team Carleton unum 3 side l"));
    }

    @Test
    void theAllocationFreeWriterWritesWhatFormatWrites() {
        byte[] message = "(see 0 ((b) 1 2))\n\u0000x".getBytes(StandardCharsets.UTF_8);
        long[] samples = {0, 1, 999_999, 1_000_000, 9_000_042, 10_500_000, 3_600_123_456L, Long.MAX_VALUE / 1000};
        for (long micros : samples) {
            for (Direction direction : Direction.values()) {
                byte[] target = new byte[28 + MessageEscapes.maxEscapedLength(message.length + 2)];
                // written from an offset inside a larger buffer, as the proxy hands datagrams over
                byte[] data = new byte[message.length + 2];
                System.arraycopy(message, 0, data, 1, message.length);
                int end = ProxyLogLine.write(micros, direction, data, 1, message.length, target);
                assertEquals(new ProxyLogLine(micros, direction, message).format(),
                        new String(target, 0, end, StandardCharsets.UTF_8));
            }
        }
    }

    @Test
    void theByteFrameReadsWhatTheWriterWrote() {
        ProxyLogLine written = new ProxyLogLine(3_000_042L, Direction.CLIENT_TO_SERVER, "(dash 100)".getBytes(StandardCharsets.UTF_8));
        byte[] bytes = written.format().getBytes(StandardCharsets.UTF_8);
        ProxyLogLine.Frame frame = ProxyLogLine.frame(bytes, bytes.length);
        assertEquals(new ProxyLogLine.Frame(3.000042, Direction.CLIENT_TO_SERVER, 13, null), frame);
        // an empty datagram: the message starts at the end, with or without the trailing space
        assertEquals(12, ProxyLogLine.frame("0.000001 s2c".getBytes(StandardCharsets.UTF_8), 12).messageStart());
        assertEquals(13, ProxyLogLine.frame("0.000001 s2c ".getBytes(StandardCharsets.UTF_8), 13).messageStart());
    }

    @Test
    void theByteFrameNamesWhatIsBroken() {
        assertEquals("expected '<seconds> <c2s|s2c> <message>'", frame("x1 c2s (dash 1)").problem());
        assertEquals("expected '<seconds> <c2s|s2c> <message>'", frame("12.5").problem());
        assertEquals("direction must be c2s or s2c", frame("12.5 c2sx (dash 1)").problem());
        assertEquals("direction must be c2s or s2c", frame("12.5 up").problem());
        // lenient about the seconds, which the strict parse is not
        assertEquals(12.5, frame("12.5 s2c (see 0)").seconds());
    }

    private static ProxyLogLine.Frame frame(String line) {
        byte[] bytes = line.getBytes(StandardCharsets.UTF_8);
        return ProxyLogLine.frame(bytes, bytes.length);
    }
}
