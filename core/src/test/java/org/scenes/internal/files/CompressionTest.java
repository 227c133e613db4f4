package org.scenes.internal.files;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Outputs compress by their name's ending; inputs decompress by their first bytes, whatever their name. */
class CompressionTest {
    @TempDir
    Path dir;

    private static final byte[] TEXT = "{\"scenes\": [1, 2, 3]}\n".repeat(2000).getBytes(StandardCharsets.UTF_8);

    private void write(Path target) throws IOException {
        try (AtomicOutput output = AtomicOutput.create(target)) {
            OutputStream out = output.stream();
            out.write(TEXT);
            output.commit();
        }
    }

    private static byte[] read(Path file) throws IOException {
        try (InputStream in = Inputs.open(file)) {
            return in.readAllBytes();
        }
    }

    @Test
    void eachNameEndingGetsItsCompressionAndEveryFileReadsBackWhateverItIsCalled() throws IOException {
        Path gzip = dir.resolve("a.json.gz");
        Path zstd = dir.resolve("a.json.zst");
        Path plain = dir.resolve("a.json");
        write(gzip);
        write(zstd);
        write(plain);
        byte[] gzipBytes = Files.readAllBytes(gzip);
        byte[] zstdBytes = Files.readAllBytes(zstd);
        assertEquals(0x1f, gzipBytes[0] & 0xff);
        assertEquals(0x8b, gzipBytes[1] & 0xff);
        assertArrayEquals(new byte[] {0x28, (byte) 0xb5, 0x2f, (byte) 0xfd}, Arrays.copyOf(zstdBytes, 4));
        assertTrue(zstdBytes.length < TEXT.length / 10, "compressed: " + zstdBytes.length);
        assertArrayEquals(TEXT, Files.readAllBytes(plain));
        // a renamed file is still read by what it holds
        Path renamed = Files.move(zstd, dir.resolve("renamed.json"));
        assertArrayEquals(TEXT, read(renamed));
        assertArrayEquals(TEXT, read(gzip));
        assertArrayEquals(TEXT, read(plain));
    }

    @Test
    void aTruncatedZstdFileFailsNamingTheFileInsteadOfEndingEarly() throws IOException {
        Path zstd = dir.resolve("cut.json.zst");
        write(zstd);
        byte[] bytes = Files.readAllBytes(zstd);
        Files.write(zstd, Arrays.copyOf(bytes, bytes.length / 2));
        Inputs.CorruptCompressionException e = assertThrows(Inputs.CorruptCompressionException.class, () -> read(zstd));
        assertTrue(e.getMessage().startsWith(zstd + ": corrupt or truncated zstd"), e.getMessage());
    }
}
