package org.scenes.internal.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.List;
import java.util.stream.Stream;
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
}
