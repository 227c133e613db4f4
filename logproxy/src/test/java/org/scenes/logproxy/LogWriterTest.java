package org.scenes.logproxy;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.scenes.proxylog.ProxyLogLine;

class LogWriterTest {
    private static String seconds(long micros) {
        byte[] target = new byte[32];
        return new String(target, 0, LogWriter.writeSeconds(target, micros), StandardCharsets.US_ASCII);
    }

    @Test
    void secondsHaveSixFractionDigitsLikeTheLineFormat() {
        long[] samples = {0, 1, 999_999, 1_000_000, 9_000_042, 10_500_000, 3_600_123_456L, Long.MAX_VALUE / 1000};
        for (long micros : samples) {
            StringBuilder expected = new StringBuilder();
            ProxyLogLine.appendSeconds(expected, micros);
            assertEquals(expected.toString(), seconds(micros));
        }
        assertEquals("10.500000", seconds(10_500_000));
    }
}
