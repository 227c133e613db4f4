package org.scenes.internal.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.api.Grid;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.testing.SharedData;

/**
 * Converting a log of more than 100 MB must work in a 256 MB heap: a child JVM with
 * {@code -Xmx256m} streams a generated 100 MB log (a game repeated, never on disk: a recorded one
 * from the shared data, or one made up here)
 * through the converter into a scene file. Loading the log or the scenes whole would fail
 * with OutOfMemoryError.
 */
@Tag("slow")
class LargeLogMemoryTest {
    static final long LOG_BYTES = 100L << 20;

    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0} game")
    @ValueSource(strings = {"recorded", "generated"})
    void a100MegabyteLogConvertsWith256MegabytesOfHeap(String game) throws IOException, InterruptedException {
        if (game.equals("recorded")) {
            SharedData.assumePresent();
        }
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path output = dir.resolve("big.json.gz");
        Process child = new ProcessBuilder(java.toString(), "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                "-Dscenes.shared=" + System.getProperty("scenes.shared", "../../shared"),
                LargeLogMemoryTest.class.getName(), output.toString(), game)
                .redirectErrorStream(true).start();
        String printed = new String(child.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(child.waitFor(5, TimeUnit.MINUTES), "child still running");
        assertEquals(0, child.exitValue(), printed);
        List<String> lines = printed.lines().toList();
        String last = lines.get(lines.size() - 1);
        assertTrue(last.startsWith("converted "), printed);
        long bytes = Long.parseLong(last.split(" ")[1]);
        assertTrue(bytes >= LOG_BYTES, "log text read: " + bytes);
        assertTrue(Long.parseLong(last.split(" ")[4]) > 0, last);
        assertTrue(Files.size(output) > 0);
    }

    /** The child: converts the generated log into the scene file named by the first argument. */
    public static void main(String[] args) throws IOException {
        byte[] game = args[1].equals("recorded") ? recordedGame() : madeUpGame();
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
            ConversionReport report = SceneConverter.with(Grid.DEFAULT).strict(true).build().convert(reader, writer::write, b -> { });
            writer.commit();
            System.out.println("converted " + report.bytes() + " bytes into " + report.scenes() + " scenes");
        }
    }

    private static byte[] recordedGame() throws IOException {
        try (InputStream in = Inputs.open(SharedData.resolve("krislet/classic-game1/Carleton_1.lsf.gz"))) {
            return in.readAllBytes();
        }
    }

    /** A 6000-cycle player log: a see of ball, goal, flag and opponent each cycle, then a dash or a turn. */
    static byte[] madeUpGame() {
        Random random = new Random(1);
        StringBuilder log = new StringBuilder("(init Home (version 9))\n(init l 1 before_kick_off)\n");
        for (int cycle = 1; cycle <= 6000; cycle++) {
            int ball = random.nextInt(40) - 20;
            log.append("(see ").append(cycle).append(" ((b) ").append(1 + random.nextInt(30)).append(' ').append(ball)
                    .append(") ((g r) ").append(20 + random.nextInt(40)).append(' ').append(random.nextInt(60) - 30)
                    .append(") ((f c) ").append(5 + random.nextInt(40)).append(' ').append(random.nextInt(90) - 45)
                    .append(") ((p \"Away\" ").append(1 + random.nextInt(11)).append(") ").append(2 + random.nextInt(30))
                    .append(' ').append(random.nextInt(90) - 45).append("))\n")
                    .append(ball == 0 ? "(dash 80)\n" : "(turn " + ball + ")\n");
        }
        return log.toString().getBytes(StandardCharsets.US_ASCII);
    }
}
