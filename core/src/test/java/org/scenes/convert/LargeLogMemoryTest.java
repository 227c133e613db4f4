package org.scenes.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.files.Inputs;
import org.scenes.scene.Grid;
import org.scenes.scene.SceneFileHeader;
import org.scenes.scene.SceneFileWriter;
import org.scenes.scene.SceneSource;

/**
 * Converting a log of more than 100 MB must work in a 256 MB heap: a child JVM with
 * {@code -Xmx256m} streams a generated 100 MB log (a recorded game repeated, never on disk)
 * through the converter into a scene file. Loading the log or the scenes whole would fail
 * with OutOfMemoryError.
 */
class LargeLogMemoryTest {
    static final long LOG_BYTES = 100L << 20;

    @TempDir
    Path dir;

    @Test
    void a100MegabyteLogConvertsWith256MegabytesOfHeap() throws IOException, InterruptedException {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path output = dir.resolve("big.json.gz");
        Process child = new ProcessBuilder(java.toString(), "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                "-Dscenes.shared=" + System.getProperty("scenes.shared", "../../shared"),
                LargeLogMemoryTest.class.getName(), output.toString())
                .redirectErrorStream(true).start();
        String printed = new String(child.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(child.waitFor(5, TimeUnit.MINUTES), "child still running");
        assertEquals(0, child.exitValue(), printed);
        List<String> lines = printed.lines().toList();
        String last = lines.get(lines.size() - 1);
        assertTrue(last.startsWith("converted "), printed);
        long bytes = Long.parseLong(last.split(" ")[1]);
        assertTrue(bytes >= LOG_BYTES, "log text read: " + bytes);
        assertTrue(Files.size(output) > 0);
    }

    /** The child: converts the generated log into the scene file named by the argument. */
    public static void main(String[] args) throws IOException {
        Path shared = Path.of(System.getProperty("scenes.shared"), "data", "krislet", "classic-game1", "Carleton_1.lsf.gz");
        byte[] game;
        try (InputStream in = Inputs.open(shared)) {
            game = in.readAllBytes();
        }
        InputStream repeated = new InputStream() {
            long served;
            int position;

            @Override
            public int read() {
                byte[] one = new byte[1];
                return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
            }

            @Override
            public int read(byte[] buffer, int offset, int length) {
                if (served >= LOG_BYTES && position == 0) { // whole games only
                    return -1;
                }
                int count = Math.min(length, game.length - position);
                System.arraycopy(game, position, buffer, offset, count);
                position = (position + count) % game.length;
                served += count;
                return count;
            }
        };
        Path target = Path.of(args[0]);
        try (LogReader reader = LogReader.read(Path.of("generated.lsf"), repeated);
             SceneFileWriter writer = SceneFileWriter.create(target, SceneFileHeader.of(Grid.DEFAULT,
                     new SceneSource("generated.lsf", null)))) {
            ConversionReport report = new SceneConverter(Grid.DEFAULT, true, null).convert(reader, writer::write, b -> { });
            writer.commit();
            System.out.println("converted " + report.bytes() + " bytes into " + report.scenes() + " scenes");
        }
    }
}
