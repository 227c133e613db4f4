package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.files.Inputs;

/** The whole bundled loop: simulate teachers, convert, play imitators in the simulator. */
class PlayCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    private int run(Object... args) {
        return cli.run(args);
    }

    @Test
    void imitatorsLearnFromSimulatedTeachersAndPlay() throws IOException {
        assertEquals(0, run("simulate", "--teams", "krislet:2,krislet:2", "--cycles", "600", "--out-dir",
                dir.resolve("logs")), cli.err());
        Path scenes = dir.resolve("teal1.json.gz");
        assertEquals(0, run("convert", dir.resolve("logs/Teal_1.lsf.gz"), "-o", scenes), cli.err());
        assertEquals(0, run("play", scenes, "--metric", "ball-goal", "--players", "2", "--opponent", "krislet:2",
                "--cycles", "300", "--out-dir", dir.resolve("play")), cli.err());
        String summary = cli.out();
        assertTrue(summary.matches("(?s)Learnt +\\d+ scenes from 1 files, counterpart knowledge, 1 recorded players;"
                + " ball-goal.*"), summary);
        assertTrue(summary.contains("Score          Imitator"), summary);
        Path log = dir.resolve("play/Imitator_1.lsf.gz");
        assertTrue(Files.isRegularFile(log));
        String text;
        try (var in = Inputs.open(log)) {
            text = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        }
        assertTrue(text.startsWith("(init Imitator (version 9))\n(init l 1 before_kick_off)\n"), text.substring(0, 80));
        // commands chosen from the scenes: Krislet's dashes and turns come back
        assertTrue(text.contains("\n(dash ") && text.contains("\n(turn "));
    }

    @Test
    void unansweredSeesKeptTeachTheImitatorToWaitAndItsCounterpartsKickOffSpot() throws IOException {
        assertEquals(0, run("simulate", "--teams", "krislet:2,krislet:2", "--cycles", "1500", "--seed", "11", "--out-dir",
                dir.resolve("logs")), cli.err());
        assertEquals(0, run("convert", dir.resolve("logs/Teal_1.lsf.gz"), dir.resolve("logs/Teal_2.lsf.gz"),
                "--out-dir", dir.resolve("keep"), "--unanswered", "keep"), cli.err());
        assertTrue(cli.out().matches("(?s).*Scene actions +none \\d+, .*"), cli.out());
        Path one = dir.resolve("keep/Teal_1.json.gz");
        Path two = dir.resolve("keep/Teal_2.json.gz");
        assertEquals(0, run("play", one, two, "--players", "2", "--opponent", "krislet:2", "--cycles", "600",
                "--out-dir", dir.resolve("play")), cli.err());
        assertTrue(cli.out().contains("counterpart knowledge, 2 recorded players"), cli.out());
        String player = text(dir.resolve("play/Imitator_2.lsf.gz"));
        String teacher = text(dir.resolve("logs/Teal_2.lsf.gz"));
        String spot = teacher.lines().filter(line -> line.startsWith("(move ")).findFirst().orElseThrow();
        // the teacher's repeated kick-off move (after a goal) is in its scenes: its imitator moves there
        assertTrue(text(two).contains("\"type\":\"move\""), "the test needs a goal in the teacher game");
        assertEquals(spot, player.lines().filter(line -> line.startsWith("(move ")).findFirst().orElseThrow());
        long sees = player.lines().filter(line -> line.startsWith("(see ")).count();
        long answered = 0;
        String previous = "";
        for (String line : player.lines().toList()) {
            if (previous.startsWith("(see ") && !line.startsWith("(")) {
                continue;
            }
            if (previous.startsWith("(see ") && (line.startsWith("(dash") || line.startsWith("(turn")
                    || line.startsWith("(kick") || line.startsWith("(move"))) {
                answered++;
            }
            previous = line;
        }
        assertTrue(answered < sees * 0.95, "some sees left unanswered, as the teacher did: " + answered + " of " + sees);
    }

    @Test
    void badRoleAndTempoOptionsAreUsageErrors() {
        assertEquals(ExitCodes.USAGE, run("play", dir.resolve("x.json"), "--knowledge", "everyone", "--out-dir", dir));
        assertTrue(cli.err().contains("counterpart or team"), cli.err());
        assertEquals(ExitCodes.USAGE, run("play", dir.resolve("x.json"), "--think-steps", "-1", "--out-dir", dir));
        assertTrue(cli.err().contains("--think-steps"), cli.err());
        assertEquals(ExitCodes.USAGE, run("convert", dir.resolve("x.lsf"), "-o", dir.resolve("x.json"),
                "--unanswered", "maybe"));
        assertTrue(cli.err().contains("keep or drop"), cli.err());
    }

    private static String text(Path file) throws IOException {
        try (var in = Inputs.open(file)) {
            return new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        }
    }

    @Test
    void playTakesOneConfiguration() {
        assertEquals(ExitCodes.USAGE, run("play", dir.resolve("x.json"), "--k", "1,3", "--out-dir", dir));
        assertTrue(cli.err().contains("one configuration"), cli.err());
    }
}
