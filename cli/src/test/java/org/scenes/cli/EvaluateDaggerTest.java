package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;

class EvaluateDaggerTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    @Test
    void daggerRoundsGrowTheKnowledgeBaseAndAreReported() throws Exception {
        Path report = dir.resolve("report");
        int status = cli.run("evaluate", "--metric", "ball-goal", "--players", "2", "--opponent", "krislet:2",
                "--cycles", "300", "--seeds", "1", "--train-games", "1", "--dagger", "1", "--json", "--report", report);
        assertEquals(ExitCodes.OK, status, cli.err());
        JsonNode root = ConfigFiles.JSON.readTree(cli.out());
        JsonNode rounds = root.get("rounds");
        assertEquals(2, rounds.size());
        int labelled = rounds.get(0).get("labelled").asInt();
        assertTrue(labelled > 100, "labelled " + labelled);
        assertEquals(rounds.get(0).get("scenes").asInt() + labelled, rounds.get(1).get("scenes").asInt());
        assertEquals(labelled, rounds.get(1).get("added").asInt());
        // the figures printed are the last round's
        assertEquals(rounds.get(1).get("agreement").asDouble(),
                root.at("/figures/agreement/imitator/mean").asDouble(), 1e-12);
        String page = Files.readString(report.resolve("index.html"));
        assertTrue(page.contains("DAgger: round 1"), "the rounds in the report");
    }

    @Test
    void daggerOutWritesEachRoundsLabelsAsSceneFilesThatTrainAnImitator() throws Exception {
        Path labels = dir.resolve("labels");
        int status = cli.run("evaluate", "--metric", "ball-goal", "--players", "2", "--opponent", "krislet:2",
                "--cycles", "300", "--seeds", "1", "--train-games", "1", "--dagger", "1", "--dagger-out", labels,
                "--json");
        assertEquals(ExitCodes.OK, status, cli.err());
        int labelled = ConfigFiles.JSON.readTree(cli.out()).get("rounds").get(0).get("labelled").asInt();
        assertTrue(cli.err().contains("DAgger labels"), cli.err());
        // round 0's labels, one file per imitating player of its one game; the last round's are never used
        List<Path> files;
        try (Stream<Path> listed = Files.list(labels.resolve("round-0"))) {
            files = listed.sorted().toList();
        }
        assertEquals(List.of("Teal_1-g1.json.gz", "Teal_2-g1.json.gz"),
                files.stream().map(f -> f.getFileName().toString()).toList());
        assertTrue(Files.notExists(labels.resolve("round-1")));
        long scenes = 0;
        for (Path file : files) {
            SceneFile read = SceneFileReader.read(file);
            assertEquals(file.getFileName().toString().startsWith("Teal_1") ? 1 : 2, read.header().source().observer().uniformNumber());
            scenes += read.scenes().size();
        }
        assertEquals(labelled, scenes, "every labelled scene, as it joined the next round");
        // they train an imitator as any recorded player's scenes do
        CommandRunner validate = new CommandRunner();
        assertEquals(ExitCodes.OK, validate.run("validate", "--train", files.get(0), "--test", files.get(1)),
                validate.err());

        // the labels never overwrite scenes learnt from
        CommandRunner over = new CommandRunner();
        assertEquals(ExitCodes.USAGE, over.run("evaluate", files.get(0), "--dagger", "1", "--dagger-out", labels));
        assertTrue(over.err().contains("--dagger-out: " + labels + " holds "), over.err());
        assertTrue(Files.exists(files.get(0)));

        CommandRunner alone = new CommandRunner();
        assertEquals(ExitCodes.USAGE, alone.run("evaluate", "--dagger-out", labels));
        assertTrue(alone.err().contains("--dagger-out: writes DAgger's labelled scenes"), alone.err());
    }

    @Test
    void daggerNeedsTheTeacherInProcess() {
        assertEquals(ExitCodes.USAGE, cli.run("evaluate", "--dagger", "1", "--teacher-games", dir, "--imitator-games",
                dir));
        assertTrue(cli.err().contains("--dagger:") && cli.err().strip().lines().count() == 1, cli.err());
        CommandRunner external = new CommandRunner();
        assertEquals(ExitCodes.USAGE, external.run("evaluate", "--dagger", "2", "--teacher-command", "./start.sh",
                "--server", "localhost:6000", "--server-logs", dir, dir.resolve("x.json")));
        assertTrue(external.err().contains("--dagger:") && external.err().contains("--teacher-command"), external.err());
        CommandRunner negative = new CommandRunner();
        assertEquals(ExitCodes.USAGE, negative.run("evaluate", "--dagger", "-1"));
        assertTrue(negative.err().contains("--dagger: must be 0 or more"), negative.err());
    }
}
