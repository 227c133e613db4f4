package org.scenes.internal.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicOutputTest {
    @TempDir
    Path dir;

    private static long deadPid() throws Exception {
        Process process = new ProcessBuilder("true").start();
        long pid = process.pid();
        process.waitFor();
        return pid;
    }

    private List<String> names() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void theTemporaryFileCarriesTheWritersPid() throws Exception {
        try (AtomicOutput output = AtomicOutput.create(dir.resolve("table.csv"))) {
            output.stream().write('x');
            String name = names().get(0);
            assertTrue(name.startsWith(".table.csv." + ProcessHandle.current().pid() + "-") && name.endsWith(".tmp"), name);
        }
        assertEquals(List.of(), names(), "closed without commit: nothing left");
    }

    /** What SIGKILL leaves (no hook runs) is removed by the next writer into the directory, and only that. */
    @Test
    void theNextWriterRemovesTemporariesOfDeadOrLongSilentWritersAndNothingElse() throws Exception {
        long dead = deadPid();
        long alive = ProcessHandle.current().pid();
        Path ofDead = Files.writeString(dir.resolve(".scenes.json.gz." + dead + "-k3x9.tmp"), "half");
        Path ofDeadOtherTarget = Files.writeString(dir.resolve(".report.html." + dead + "-a1.tmp"), "half");
        Path ofLive = Files.writeString(dir.resolve(".scenes.json.gz." + alive + "-zz.tmp"), "being written");
        Path ofLiveButSilent = Files.writeString(dir.resolve(".other.csv." + alive + "-q.tmp"), "old");
        Files.setLastModifiedTime(ofLiveButSilent, FileTime.from(Instant.now().minus(AtomicOutput.STALE_AFTER).minusSeconds(60)));
        Path userFile = Files.writeString(dir.resolve(".notes.tmp"), "mine");
        Path oldPattern = Files.writeString(dir.resolve(".scenes.json.gz.k3x9.tmp"), "no pid: not ours to judge");

        try (AtomicOutput output = AtomicOutput.create(dir.resolve("scenes.json.gz"))) {
            output.stream().write("new".getBytes(StandardCharsets.UTF_8));
            output.commit();
        }

        assertTrue(Files.exists(dir.resolve("scenes.json.gz")));
        assertTrue(Files.notExists(ofDead), "a dead writer's temporary is removed");
        assertTrue(Files.notExists(ofDeadOtherTarget), "of any target in the directory");
        assertTrue(Files.notExists(ofLiveButSilent), "a temporary untouched for hours is stale whatever its PID");
        assertTrue(Files.exists(ofLive), "a live writer's temporary stays");
        assertTrue(Files.exists(userFile) && Files.exists(oldPattern), "other files stay: " + names());
    }

    // ---- issue 31.2: only regular files are replaced --------------------------------------

    private static void write(Path target, String text) throws IOException {
        try (AtomicOutput output = AtomicOutput.create(target)) {
            output.stream().write(text.getBytes(StandardCharsets.UTF_8));
            output.commit();
        }
    }

    @Test
    void aSymbolicLinkIsWrittenThroughAndStaysALink() throws Exception {
        Path real = Files.writeString(dir.resolve("real.csv"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("link.csv"), Path.of("real.csv"));
        write(link, "new");
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        assertEquals("new", Files.readString(real));
        Path dangling = Files.createSymbolicLink(dir.resolve("dangling.csv"), dir.resolve("sub/made.csv"));
        write(dangling, "made");
        assertTrue(Files.isSymbolicLink(dangling));
        assertEquals("made", Files.readString(dir.resolve("sub/made.csv")));
    }

    @Test
    void aCharacterDeviceIsWrittenThroughNotReplaced() throws Exception {
        Path devNull = Path.of("/dev/null");
        Assumptions.assumeTrue(Files.exists(devNull), "no /dev/null here");
        Path link = Files.createSymbolicLink(dir.resolve("sink"), devNull);
        write(link, "gone");
        assertTrue(Files.isSymbolicLink(link));
        assertFalse(Files.isRegularFile(devNull), "/dev/null is still a device");
    }

    @Test
    void aFifoIsWrittenThroughAsAStream() throws Exception {
        Path fifo = dir.resolve("pipe");
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        Assumptions.assumeTrue(mkfifo.waitFor() == 0, "mkfifo is not available");
        CompletableFuture<String> read = CompletableFuture.supplyAsync(() -> {
            try {
                return Files.readString(fifo);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        });
        write(fifo, "through the pipe");
        assertEquals("through the pipe", read.get(20, TimeUnit.SECONDS));
        assertFalse(Files.isRegularFile(fifo), "the FIFO is still a FIFO");
    }

    @Test
    void aWriteErrorNamesTheTargetAndTheReason() throws Exception {
        Path full = Path.of("/dev/full");
        Assumptions.assumeTrue(Files.exists(full), "no /dev/full here");
        Path link = Files.createSymbolicLink(dir.resolve("out.csv"), full);
        IOException error = assertThrows(IOException.class, () -> {
            try (AtomicOutput output = AtomicOutput.create(link)) {
                output.stream().write(new byte[1 << 17]);
                output.commit();
            }
        });
        assertTrue(error.getMessage().startsWith(link + ": cannot write: "), error.getMessage());
        assertTrue(error.getMessage().contains("No space left"), error.getMessage());
        assertFalse(Files.isRegularFile(full), "/dev/full is still a device");
    }

    @Test
    void onceTheOutputsAreAbandonedNoneOpensSoNoTemporaryFileOutlivesTheStop() throws Exception {
        // a command's threads run on while its shutdown hook abandons the outputs: one opening then would stay
        Path earlier = dir.resolve("earlier.txt");
        Path later = dir.resolve("later.txt");
        try (AtomicOutput open = AtomicOutput.create(earlier)) {
            open.stream().write("half".getBytes(StandardCharsets.US_ASCII));
            assertEquals(List.of(earlier.toAbsolutePath()), AtomicOutput.abandonAll());
            IOException refused = assertThrows(IOException.class, () -> AtomicOutput.create(later));
            assertEquals(later + ": not written: the command is stopping", refused.getMessage());
            assertEquals(List.of(), names(), "neither target nor temporary file");
        } finally {
            AtomicOutput.resumeAfterAbandon();
        }
        write(later, "whole");
        assertEquals(List.of("later.txt"), names());
    }

    @Test
    void aDirectoryIsRefused() throws Exception {
        Path sub = Files.createDirectory(dir.resolve("sub"));
        IOException error = assertThrows(IOException.class, () -> AtomicOutput.create(sub));
        assertTrue(error.getMessage().contains("is a directory"), error.getMessage());
    }
}
