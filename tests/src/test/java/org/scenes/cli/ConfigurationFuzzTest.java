package org.scenes.cli;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Jazzer fuzz test of the configuration reader (package-private, hence this package); see ReadersFuzzTest. */
class ConfigurationFuzzTest {
    @FuzzTest(maxDuration = "60s")
    void configurationReader(byte[] data) throws IOException {
        Path file = Files.createTempFile("fuzz", ".json");
        try {
            Files.write(file, data);
            ConfigFiles.read(file);
        } catch (UsageException documented) {
            // an unknown or ill-typed key, or not JSON: said naming the file
        } finally {
            Files.delete(file);
        }
    }
}
