package org.scenes.testing;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Assumptions;

/**
 * The real recordings of the shared data set: {@code ../shared/data} beside the clone, found
 * through the {@code scenes.shared} property the build sets. A fresh clone has none; CI has them.
 * Tests that need them are annotated {@link RequiresSharedData} (or call {@link #assumePresent()})
 * and are skipped, with {@link #absentMessage()}, when they are absent; what they check that does
 * not depend on real data is checked on simulated games too.
 */
public final class SharedData {
    private SharedData() {
    }

    /** The shared data set's {@code data} directory, which holds {@code krislet/} and {@code rcssserver19/}. */
    public static Path data() {
        return Path.of(System.getProperty("scenes.shared", "../../shared"), "data").toAbsolutePath().normalize();
    }

    /** A file or directory under {@link #data()}, for example {@code krislet/classic-game1/Carleton_1.lsf.gz}. */
    public static Path resolve(String relative) {
        return data().resolve(relative);
    }

    public static boolean present() {
        return Files.isDirectory(data());
    }

    /** Why a test was skipped: the same text for every test, so a report can group them. */
    public static String absentMessage() {
        return "needs the shared real recordings, absent here: no " + data()
                + " (a fresh clone has no ../shared beside it; CI has it)";
    }

    /** Skips the calling test (a JUnit assumption) when the shared recordings are absent. */
    public static void assumePresent() {
        Assumptions.assumeTrue(present(), SharedData::absentMessage);
    }
}
