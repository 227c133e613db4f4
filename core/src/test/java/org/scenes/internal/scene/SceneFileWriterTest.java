package org.scenes.internal.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.api.World;

/** The writer's own number text is the text {@link Double#toString} gives (files stay as they were). */
class SceneFileWriterTest {
    @TempDir
    Path dir;

    /**
     * Tenths and hundredths, the values of sees and world models, skip {@code Double.toString}: every
     * value written must read as that method's text, also tiny, negative and large ones, and values
     * that are not quite a hundredth.
     */
    @Test
    void numbersAreWrittenAsDoubleToStringWritesThem() throws IOException {
        List<Double> values = new ArrayList<>();
        for (long k = -200_000; k <= 200_000; k += 7) {
            values.add(k / 100.0);
        }
        for (double v : new double[] {0.01, -0.01, 0.05, -0.04, 0.001, 1e-5, 123456.78, -999999.99, 999999.9,
                1_000_000.01, 12.345, 0.1 + 0.2, 1.0 / 3, -0.0, 7312, 0.9, 1e15 + 0.5, 3.14159}) {
            values.add(v);
        }
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i + 4 <= values.size(); i += 4) {
            World world = new World(values.get(i), values.get(i + 1), 0, 0, values.get(i + 2), values.get(i + 3),
                    Double.NaN, Double.NaN, 0, Double.NaN, Double.NaN, Double.NaN, Double.NaN, -1, List.of(), "",
                    0, 0);
            scenes.add(new Scene(i, SceneFixtures.OBSERVER, List.of(), List.of(Action.turn(30)), null, 0, world));
        }
        Path file = dir.resolve("numbers.json");
        SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT,
                new SceneSource("numbers", SceneFixtures.OBSERVER)), scenes));

        Matcher written = Pattern.compile("\"world\":\\{\"x\":([^,]+),\"y\":([^,]+),\"body\":0,\"neck\":0,"
                + "\"vx\":([^,]+),\"vy\":([^,]+),").matcher(Files.readString(file));
        int checked = 0;
        while (written.find()) {
            for (int g = 1; g <= 4; g++) {
                double value = values.get(checked);
                String expected = value == Math.rint(value) && Math.abs(value) < 1e15
                        && Double.doubleToRawLongBits(value) != Double.doubleToRawLongBits(-0.0)
                        ? Long.toString((long) value) : Double.toString(value);
                assertEquals(expected, written.group(g), "value " + checked);
                checked++;
            }
        }
        assertEquals(values.size() / 4 * 4, checked);
    }
}
