package org.scenes.testing;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The processes a test started, found by their command lines in /proc (ProcessHandle's command
 * line is empty for a JVM with a class path as long as a test's).
 */
public final class Processes {
    private Processes() {
    }

    /** The processes other than this JVM whose command line holds {@code marker}. */
    public static List<ProcessHandle> running(String marker) throws IOException {
        List<ProcessHandle> found = new ArrayList<>();
        try (Stream<Path> entries = Files.list(Path.of("/proc"))) {
            for (Path entry : entries.filter(e -> e.getFileName().toString().matches("\\d+")).toList()) {
                String line;
                try {
                    line = new String(Files.readAllBytes(entry.resolve("cmdline")), StandardCharsets.UTF_8)
                            .replace('\0', ' ');
                } catch (IOException gone) {
                    continue; // ended while listed
                }
                long pid = Long.parseLong(entry.getFileName().toString());
                if (line.contains(marker) && pid != ProcessHandle.current().pid()) {
                    ProcessHandle.of(pid).ifPresent(found::add);
                }
            }
        }
        return found;
    }

    /** Fails while such a process runs, after a moment for the kernel to reap those just ended. */
    public static void assertNoneRunning(String marker) throws IOException, InterruptedException {
        Thread.sleep(300);
        List<String> left = new ArrayList<>();
        for (ProcessHandle process : running(marker)) {
            left.add(process.pid() + ": " + process.info().commandLine().orElse(marker));
        }
        assertTrue(left.isEmpty(), "still running: " + left);
    }
}
