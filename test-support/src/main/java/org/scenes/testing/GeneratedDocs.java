package org.scenes.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A docs page generated from code (an options table): the test writes what the code gives under
 * the module's build directory and fails while the page in docs/ differs, naming the file to copy.
 */
public final class GeneratedDocs {
    private GeneratedDocs() {
    }

    /**
     * @param written where the generated page goes, relative to the project root
     * @param docs the page in docs/, relative to the project root
     */
    public static void assertCurrent(String generated, String written, String docs) throws IOException {
        Path root = Path.of(System.getProperty("scenes.root", "."));
        Path output = root.resolve(written);
        Files.createDirectories(output.getParent());
        Files.writeString(output, generated, StandardCharsets.UTF_8);
        Path page = root.resolve(docs);
        assertTrue(Files.exists(page), page + " is missing: copy " + output + " there");
        assertEquals(generated, Files.readString(page, StandardCharsets.UTF_8),
                docs + " is stale: copy " + output + " over it");
    }
}
