package org.scenes.internal.gamelog;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The game log's numbers read without {@link Double#parseDouble} are the doubles it gives (frames stay as they were). */
class PlainDecimalTest {
    @Test
    void plainDecimalsAreWhatParseDoubleReads() {
        Random random = new Random(30);
        for (int i = 0; i < 200_000; i++) {
            StringBuilder text = new StringBuilder();
            int sign = random.nextInt(4);
            text.append(sign == 0 ? "-" : sign == 1 ? "+" : "");
            int digits = 1 + random.nextInt(17);
            int point = random.nextInt(digits + 2) - 1;
            for (int d = 0; d < digits; d++) {
                if (d == point) {
                    text.append('.');
                }
                text.append((char) ('0' + random.nextInt(10)));
            }
            if (point == digits) {
                text.append('.');
            }
            String number = text.toString();
            double plain = GameLogReader.plainDecimal(number);
            if (!Double.isNaN(plain)) {
                assertEquals(Double.doubleToRawLongBits(Double.parseDouble(number)), Double.doubleToRawLongBits(plain),
                        number);
            } else {
                assertTrue(digits > 15, number);
            }
        }
    }

    @Test
    void otherTextIsLeftToParseDouble() {
        for (String text : new String[] {"", "-", "+", ".", "1e5", "1.2.3", "0x10", "NaN", "Infinity", "1d", " 1", "--1"}) {
            assertTrue(Double.isNaN(GameLogReader.plainDecimal(text)), text);
        }
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(GameLogReader.plainDecimal("-0")));
        assertEquals(0.5, GameLogReader.plainDecimal(".5"));
        assertEquals(5.0, GameLogReader.plainDecimal("5."));
    }
}
