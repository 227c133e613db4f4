package org.scenes.internal.validate;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.internal.protocol.ViewWidth;
import org.scenes.internal.target.Replay;

class MatchConfigFileTest {
    @TempDir
    Path dir;

    private static MatchConfig tuned() {
        return new MatchConfig("continuous", Map.of("row-weight", "0.5", "metric", "euclidean"),
                ObjectWeights.parse("1/0/0.5/1/0/1/2/1"), ActionWeights.parse("kick=2,turn_neck=0"), 5,
                "vote", Map.of("params", "average"), List.of("mirror", "memory"), 42L)
                .withReplay(Replay.TARGET).withView(ViewWidth.NARROW);
    }

    @Test
    void whatIsWrittenIsReadBack() throws Exception {
        Path file = dir.resolve("tuned.json");
        Map<String, Object> score = new LinkedHashMap<>();
        score.put("score", 0.75);
        score.put("trainFiles", List.of("a.json", "b.json"));
        MatchConfigFile.write(file, tuned(), Map.of("crossValidation", score));
        assertEquals(tuned(), MatchConfigFile.read(file));
        MatchConfigFile.write(file, MatchConfig.DEFAULT, Map.of());
        assertEquals(MatchConfig.DEFAULT, MatchConfigFile.read(file));
        assertTrue(!Files.readString(file).contains("\"view\""), "no view written when the server's is kept");
    }

    @Test
    void theKeysComeInTheFilesOrderWithTheExtraLast() throws Exception {
        Path file = dir.resolve("tuned.json");
        MatchConfigFile.write(file, tuned(), Map.of("crossValidation", Map.of("score", 0.5)));
        String text = Files.readString(file);
        int last = -1;
        for (String key : MatchConfigFile.KEYS) {
            int at = text.indexOf("\"" + key + "\" :");
            assertTrue(at > last, key + " out of order in\n" + text);
            last = at;
        }
        assertTrue(text.startsWith("{\n  \"metric\" : \"continuous\",\n  \"options\" : {\n    \"metric\" : \"euclidean\","), text);
    }

    @Test
    void aStreamGetsTheSameBytesAsAFile() throws Exception {
        Path file = dir.resolve("tuned.json");
        MatchConfigFile.write(file, tuned(), Map.of("crossValidation", 1));
        ByteArrayOutputStream stream = new ByteArrayOutputStream();
        MatchConfigFile.write(stream, tuned(), Map.of("crossValidation", 1));
        assertArrayEquals(Files.readAllBytes(file), stream.toByteArray());
    }

    @Test
    void aBadFileIsRefusedNamingTheFileAndKey() throws Exception {
        Path file = dir.resolve("bad.json");
        Files.writeString(file, "{\"k\": \"many\"}", StandardCharsets.UTF_8);
        var error = assertThrows(MatchConfigFile.InvalidException.class, () -> MatchConfigFile.read(file));
        assertEquals(file + ": key 'k' must be an integer, not \"many\"", error.getMessage());
        Files.writeString(file, "{\"metrc\": \"cell\"}", StandardCharsets.UTF_8);
        error = assertThrows(MatchConfigFile.InvalidException.class, () -> MatchConfigFile.read(file));
        assertTrue(error.getMessage().startsWith(file + ": unknown key 'metrc'"), error.getMessage());
        Files.writeString(file, "{\"k\": 0}", StandardCharsets.UTF_8);
        error = assertThrows(MatchConfigFile.InvalidException.class, () -> MatchConfigFile.read(file));
        assertEquals(file + ": k must be at least 1, not 0", error.getMessage());
        Files.writeString(file, "{\"view\": \"tiny\"}", StandardCharsets.UTF_8);
        error = assertThrows(MatchConfigFile.InvalidException.class, () -> MatchConfigFile.read(file));
        assertEquals(file + ": unknown view 'tiny': use one of narrow, normal, wide", error.getMessage());
        Path missing = dir.resolve("missing.json");
        error = assertThrows(MatchConfigFile.InvalidException.class, () -> MatchConfigFile.read(missing));
        assertEquals(missing + ": no such configuration file", error.getMessage());
    }
}
