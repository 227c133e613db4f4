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
        assertTrue(summary.matches("(?s)Learnt +\\d+ scenes from 1 files; ball-goal.*"), summary);
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
    void playTakesOneConfiguration() {
        assertEquals(ExitCodes.USAGE, run("play", dir.resolve("x.json"), "--k", "1,3", "--out-dir", dir));
        assertTrue(cli.err().contains("one configuration"), cli.err());
    }
}
