package org.scenes.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/** {@code scenes-spark convert ARCHIVE_DIR} writes what {@code scenes convert ARCHIVE_DIR} writes, and resumes. */
class SparkArchiveTest {
    @TempDir
    Path work;

    private Path simulated(Path directory, int seed) throws IOException {
        Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Carleton", 2, Teachers.byName("krislet")),
                new GameSetup.Team("University", 2, Teachers.byName("krislet")), 400, seed,
                work.resolve("players" + seed))).recordTo(directory);
        simulator.run(t -> { });
        return simulator.recorded().get(0);
    }

    private static void gzip(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file);
             OutputStream out = new GZIPOutputStream(Files.newOutputStream(file.resolveSibling(file.getFileName() + ".gz")))) {
            in.transferTo(out);
        }
        Files.delete(file);
    }

    @Test
    void theArchiveModeWritesTheFilesAndManifestOfScenesConvertAndResumes() throws IOException {
        Path archive = work.resolve("archive");
        simulated(archive.resolve("day1"), 1);
        Path nested = simulated(archive.resolve("day2/late"), 2);
        gzip(nested);
        gzip(nested.resolveSibling(nested.getFileName().toString().replace(".rcg", ".rcl")));
        Path alone = simulated(archive.resolve("day3"), 3);
        Files.delete(alone.resolveSibling(alone.getFileName().toString().replace(".rcg", ".rcl")));

        Path out = work.resolve("spark-out");
        SparkJobsTest.Run job = SparkJobsTest.spark("convert", archive.toString(), "--out-dir", out.toString());
        assertEquals(0, job.status(), job.err());
        // the game without its command log: commands inferred from the game log, as scenes convert does by default
        assertTrue(job.out().contains("Converted              3 (0 of them by an earlier run"), job.out());

        Path expected = work.resolve("local-out");
        SparkJobsTest.Run local = SparkJobsTest.local("convert", archive.toString(), "--out-dir", expected.toString());
        assertEquals(0, local.status(), local.err());
        List<Path> localFiles = SparkJobsTest.files(expected);
        assertEquals(localFiles.stream().map(expected::relativize).toList(),
                SparkJobsTest.files(out).stream().map(out::relativize).toList(), "the same files: scenes, records, manifest");
        assertEquals(3 * 4 + 3 + 1, localFiles.size());
        for (Path file : localFiles) {
            Path written = out.resolve(expected.relativize(file).toString());
            if (file.getFileName().toString().endsWith(".gz")) {
                assertEquals(SparkJobsTest.gunzip(file), SparkJobsTest.gunzip(written), file.toString());
            } else {
                assertEquals(Files.readString(file), Files.readString(written), file.toString());
            }
        }

        SparkJobsTest.Run again = SparkJobsTest.spark("convert", archive.toString(), "--out-dir", out.toString());
        assertEquals(0, again.status(), again.err());
        assertTrue(again.out().contains("Converted              3 (3 of them by an earlier run"), again.out());
    }
}
