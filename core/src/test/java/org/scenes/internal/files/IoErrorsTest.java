package org.scenes.internal.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.convert.LogReader;
import org.scenes.internal.scene.SceneFileReader;

/** A file that cannot be read is named with the reason, not with its name twice. */
class IoErrorsTest {
    @TempDir
    Path directory;

    @Test
    void aPermissionDeniedSaysSo() {
        // its own message is only the file's name (root reads every file, so no chmod can show it here)
        AccessDeniedException denied = new AccessDeniedException("/some/file.json");
        assertEquals("/some/file.json", denied.getMessage());
        assertEquals("permission denied", IoErrors.reason(denied));
        assertEquals("disk on fire", IoErrors.reason(new IOException("disk on fire")));
    }

    @Test
    void readersNameTheFileAndWhyItCannotBeOpened() throws IOException {
        Path folder = Files.createDirectory(directory.resolve("scenes.json"));
        RuntimeException scene = assertThrows(RuntimeException.class, () -> SceneFileReader.open(folder));
        assertEquals(folder + ": cannot open: Is a directory", scene.getMessage());
        RuntimeException log = assertThrows(RuntimeException.class, () -> LogReader.open(folder));
        assertEquals(folder + ": cannot open: Is a directory", log.getMessage());
    }
}
