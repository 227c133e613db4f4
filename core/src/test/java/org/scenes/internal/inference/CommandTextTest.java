package org.scenes.internal.inference;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.scenes.internal.protocol.CommandType;

/** An inferred command's text: its numbers as {@code String.format("%.3f")} trimmed writes them. */
class CommandTextTest {
    /** The text the inferred command logs had: formatted, trailing zeros and point cut, -0 as 0. */
    private static String formatted(double value) {
        String text = String.format(Locale.ROOT, "%.3f", value);
        text = text.contains(".") ? text.replaceAll("0+$", "").replaceAll("\\.$", "") : text;
        return text.equals("-0") ? "0" : text;
    }

    @Test
    void numbersAreRoundedAsTheFormatterRoundsThem() {
        SplittableRandom random = new SplittableRandom(7);
        for (int i = 0; i < 300_000; i++) {
            long thousandths = random.nextLong(-2_000_000, 2_000_000);
            double value = switch (i % 5) {
                case 0 -> (random.nextDouble() - 0.5) * 400;
                case 1 -> Math.pow(10, random.nextDouble() * 12 - 5) * (random.nextBoolean() ? 1 : -1);
                case 2 -> thousandths / 2000.0; // halves of a thousandth: the rounding's ties
                case 3 -> Math.nextUp(thousandths / 2000.0);
                default -> Math.nextDown(thousandths / 2000.0);
            };
            assertEquals(formatted(value), CommandInference.Command.num(value), "value " + value);
        }
        for (double value : new double[] {0, -0.0, 1e-3, -1e-3, 5e-4, -4e-4, 0.9995, -99.9995, 1e7, 1e7 - 0.0005,
                123456.7895, 1e-9, 3e12, Double.NaN}) {
            assertEquals(formatted(value), CommandInference.Command.num(value), "value " + value);
        }
    }

    @Test
    void commandsReadAsAPlayerWritesThem() {
        assertEquals("(dash 100 -45.5)", new CommandInference.Command(CommandType.DASH, 100, -45.5, 0, 0).text());
        assertEquals("(turn 0.125)", new CommandInference.Command(CommandType.TURN, 0.1245, Double.NaN, 0, 0).text());
        assertEquals("(turn_neck 0)", new CommandInference.Command(CommandType.TURN_NECK, -0.0001, 0, 0, 0).text());
    }
}
