package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Scene;
import org.scenes.internal.scene.SceneFileReader;

/** convert on logs shaped like a librcsc player's (generated here), and on logs that give no scenes. */
class ModernConvertCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    /** Protocol 18, synchronous vision, a see every other cycle, a cycle's commands in one line. */
    private Path modernLog(int cycles) throws IOException {
        List<String> lines = new ArrayList<>(List.of("(init HELIOS_base (version 18))", "(init r 4 before_kick_off)",
                "(synch_see)", "(ok synch_see)"));
        for (int t = 1; t <= cycles; t++) {
            lines.add("(sense_body " + t + " (view_mode high normal))");
            if (t % 2 == 0) {
                lines.add("(see " + t + " ((b) 4 " + t % 20 + ") ((g l) 30 -5))");
            }
            lines.add((t % 2 == 0 ? "(turn 0)" : "(dash 60 -30)") + "(turn_neck " + (t % 5) + ")(done)");
        }
        Path log = dir.resolve("helios_4.lsf");
        Files.write(log, lines);
        return log;
    }

    @Test
    void aModernLogGivesAScenePerCycle() throws IOException {
        Path target = dir.resolve("helios.json");
        assertEquals(0, cli.run("convert", modernLog(100), "-o", target), cli.err());
        List<Scene> scenes = SceneFileReader.read(target).scenes();
        assertEquals(99, scenes.size(), "every cycle after the first see");
        assertTrue(cli.out().contains("Scene per cycle        1 of 1 logs"), cli.out());
        assertTrue(cli.out().contains("scenes by see age 0: 50, 1: 49"), cli.out());
        assertTrue(cli.out().contains("Malformed lines        0"), cli.out());

        Path perSee = dir.resolve("per-see.json");
        assertEquals(0, cli.run("convert", modernLog(100), "-o", perSee, "--pairing", "see"), cli.err());
        assertEquals(50, SceneFileReader.read(perSee).scenes().size());
        assertEquals(2, cli.run("convert", modernLog(10), "-o", perSee, "--pairing", "sometimes"));
    }

    @Test
    void aLogWithMessagesButNoSceneFailsAndWritesNothing() throws IOException {
        Path log = dir.resolve("server_only.lsf");
        Files.write(log, List.of("(init A (version 9))", "(init l 1 before_kick_off)", "(server_param (a 1))"));
        Path target = dir.resolve("none.json");
        assertEquals(1, cli.run("convert", log, "-o", target));
        assertTrue(cli.err().contains(log + ": no scenes from 3 lines (0 see, 0 commands, 0 malformed lines): no see at all"),
                cli.err());
        assertFalse(Files.exists(target));

        Path out = dir.resolve("out");
        assertEquals(1, cli.run("convert", log, modernLog(10), "--out-dir", out));
        assertFalse(Files.exists(out.resolve("server_only.json.gz")));
        assertTrue(Files.exists(out.resolve("helios_4.json.gz")), "the other log is still converted");
        assertTrue(cli.err().contains("1 of 2 logs gave no scenes"), cli.err());

        Path empty = dir.resolve("empty.lsf");
        Files.write(empty, List.of());
        assertEquals(0, cli.run("convert", empty, "-o", dir.resolve("empty.json")), cli.err());
    }

    @Test
    void aCoachLogIsSaidToBeOneInOneLine() throws IOException {
        Path coach = dir.resolve("coach.lsf");
        Files.write(coach, List.of("(init HELIOS_base (version 18))", "(init r ok)",
                "(see_global 1 ((g l) -52.5 0) ((b) 0 0 0 0))"));
        assertEquals(1, cli.run("convert", coach, "-o", dir.resolve("coach.json")));
        assertEquals(1, cli.err().strip().lines().count(), cli.err());
        assertTrue(cli.err().contains(coach + ":2: this is an online coach's log"), cli.err());
    }

    @Test
    void validatePrintsTheBaselinesBesideEveryAccuracy() throws IOException {
        Path scenes = dir.resolve("helios.json");
        assertEquals(0, cli.run("convert", modernLog(200), "-o", scenes), cli.err());
        assertEquals(0, cli.run("validate", "--train", scenes, "--self", "--metric", "ball-goal"), cli.err());
        String text = cli.out();
        for (String line : List.of("Action accuracy", "Body action", "Neck action", "Body and neck")) {
            String row = text.lines().filter(l -> l.startsWith(line)).findFirst().orElseThrow();
            assertTrue(row.contains("baselines: majority (") && row.contains("repeat previous"), row);
        }
        assertTrue(text.contains("body classes           noop 100, dash 99"), text);
        assertTrue(text.contains("dash direction error"), text);

        assertEquals(0, cli.run("validate", "--train", scenes, "--self", "--metric", "ball-goal", "--json"), cli.err());
        com.fasterxml.jackson.databind.JsonNode body = new com.fasterxml.jackson.databind.ObjectMapper()
                .readTree(cli.out()).path("labels").path("bodyAccuracy");
        assertEquals(1.0, body.path("accuracy").asDouble(), "one view, two cycles: the see age tells them apart");
        assertEquals(0.0, body.path("repeatPreviousBaseline").asDouble(-1), "body alternates dash / noop");
        assertEquals("noop", body.path("majorityClass").asText());

        Path half = dir.resolve("half.json");
        assertEquals(0, cli.run("convert", modernLog(120), "-o", half), cli.err());
        assertEquals(0, cli.run("validate", "--folds", scenes, half, "--metric", "ball-goal"), cli.err());
        assertTrue(cli.out().contains("bodyAccuracyRepeatPrevious"), cli.out());
        assertTrue(cli.out().contains("accuracyMajority"), cli.out());
    }

    @Test
    void exportAndStatsShowBodyNeckAndSeeAge() throws IOException {
        Path scenes = dir.resolve("helios.json");
        assertEquals(0, cli.run("convert", modernLog(20), "-o", scenes), cli.err());
        assertEquals(0, cli.run("export", "--format", "csv", scenes, "--label", "both", "--see-age", "--players", "0"),
                cli.err());
        List<String> rows = cli.out().lines().toList();
        assertTrue(rows.get(0).endsWith(",unknown_players,see_age,both"), rows.get(0));
        assertTrue(rows.get(1).startsWith("2,") && rows.get(1).endsWith(",0,noop+turn_neck"), rows.get(1));
        assertTrue(rows.get(2).startsWith("3,") && rows.get(2).endsWith(",1,dash+turn_neck"), rows.get(2));
        assertEquals(0, cli.run("export", "--format", "arff", scenes, "--label", "neck"), cli.err());
        assertTrue(cli.out().contains("@attribute neck {none,noop,turn_neck}"), cli.out());
        assertEquals(0, cli.run("stats", scenes), cli.err());
        assertTrue(cli.out().contains("See age (cycles)         0 10, 1 9"), cli.out());
        assertTrue(cli.out().contains("Body classes             noop 10, dash 9"), cli.out());
    }
}
