package org.scenes.fuzz;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.scenes.api.Grid;
import org.scenes.internal.convert.LogException;
import org.scenes.internal.convert.LogReader;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.ProtocolException;
import org.scenes.internal.scene.SceneFileException;
import org.scenes.internal.scene.SceneFileReader;

/**
 * Jazzer fuzz tests of the readers. Under {@code gradle test} they run in Jazzer's regression
 * mode: every input of the seed corpus ({@code src/test/resources/org/scenes/fuzz/ReadersFuzzTestInputs/})
 * once, in seconds. {@code JAZZER_FUZZ=1} fuzzes one of them for its {@code maxDuration}
 * (docs/reliability.md). The allowed outcomes are a result or the reader's documented error;
 * any other exception, a hang or unbounded memory fails. Crashes found become corpus files.
 */
class ReadersFuzzTest {
    @FuzzTest(maxDuration = "60s")
    void messageParser(byte[] data) {
        try {
            new MessageParser().parseAll(data, 0, data.length, message -> { });
        } catch (ProtocolException documented) {
            // a malformed message, said so
        }
    }

    @FuzzTest(maxDuration = "60s")
    void logReader(byte[] data) throws IOException {
        try (LogReader reader = LogReader.read(Path.of("fuzz.log"), new ByteArrayInputStream(data))) {
            while (reader.next()) {
                reader.text();
            }
        } catch (LogException documented) {
            // not a log, or a line over the cap
        }
    }

    @FuzzTest(maxDuration = "60s")
    void converter(byte[] data) throws IOException {
        Path file = Files.createTempFile("fuzz", ".log");
        try {
            Files.write(file, data);
            SceneConverter.with(Grid.DEFAULT).build().convert(file, scene -> { });
        } catch (LogException documented) {
            // the log's error, naming it
        } finally {
            Files.delete(file);
        }
    }

    @FuzzTest(maxDuration = "60s")
    void sceneFileReader(byte[] data) throws IOException {
        Path file = Files.createTempFile("fuzz", ".json");
        try {
            Files.write(file, data);
            SceneFileReader.read(file);
        } catch (SceneFileException documented) {
            // the scene file's error, naming it
        } finally {
            Files.delete(file);
        }
    }
}
