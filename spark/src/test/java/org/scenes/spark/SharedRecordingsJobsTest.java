package org.scenes.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/** On the shared Krislet recordings: the convert job's scene files and a sweep's rows equal the local commands'. */
@RequiresSharedData
@Tag("slow")
class SharedRecordingsJobsTest {
    @TempDir
    Path work;

    @Test
    void convertAndSweepClassicGameOneAsTheLocalCommandsDo() throws IOException {
        Path game = SharedData.resolve("krislet/classic-game1");
        List<String> logs = new ArrayList<>();
        try (Stream<Path> list = Files.list(game)) {
            list.filter(p -> p.getFileName().toString().matches("Carleton_[123]\\.lsf\\.gz")).sorted()
                    .forEach(p -> logs.add(p.toString()));
        }
        List<String> args = new ArrayList<>(List.of("convert"));
        args.addAll(logs);
        args.addAll(List.of("--out-dir", work.resolve("local").toString()));
        SparkJobsTest.Run local = SparkJobsTest.local(args.toArray(String[]::new));
        assertEquals(0, local.status(), local.err());
        args.set(args.size() - 1, work.resolve("spark").toString());
        SparkJobsTest.Run job = SparkJobsTest.spark(args.toArray(String[]::new));
        assertEquals(0, job.status(), job.err());
        for (Path file : SparkJobsTest.files(work.resolve("local"))) {
            assertEquals(SparkJobsTest.gunzip(file),
                    SparkJobsTest.gunzip(work.resolve("spark/classic-game1").resolve(file.getFileName())), file.toString());
        }

        StringBuilder data = new StringBuilder();
        for (int player = 1; player <= 3; player++) {
            data.append(player == 1 ? "" : ", ").append('\'')
                    .append(work.resolve("spark/classic-game1/Carleton_" + player + ".json.gz").toString().replace("\\", "/"))
                    .append('\'');
        }
        Path sweep = Files.writeString(work.resolve("krislet.groovy"), """
                title 'Krislet classic game 1'
                data %s
                metrics 'ball-goal'
                k 1, 5
                selectors 'first-valid', 'vote'
                table columns: 'k'
                """.formatted(data));
        SparkJobsTest.Run expected = SparkJobsTest.local("experiment", sweep.toString(), "--out-dir",
                work.resolve("local-results").toString());
        assertEquals(0, expected.status(), expected.err());
        SparkJobsTest.Run distributed = SparkJobsTest.spark("experiment", sweep.toString(), "--out-dir",
                work.resolve("spark-results").toString());
        assertEquals(0, distributed.status(), distributed.err());
        assertEquals(Files.readString(work.resolve("local-results/krislet.csv")),
                Files.readString(work.resolve("spark-results/krislet.csv")));
    }
}
