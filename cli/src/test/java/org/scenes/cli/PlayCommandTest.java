package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.files.Inputs;
import picocli.CommandLine;

/** The whole bundled loop: simulate teachers, convert, play imitators in the simulator. */
class PlayCommandTest {
    @TempDir
    Path dir;

    private StringWriter out = new StringWriter();
    private StringWriter err = new StringWriter();

    private int run(Object... args) {
        out = new StringWriter();
        err = new StringWriter();
        CommandLine commandLine = ScenesCommand.commandLine();
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        String[] strings = new String[args.length];
        for (int i = 0; i < args.length; i++) {
            strings[i] = args[i].toString();
        }
        return commandLine.execute(strings);
    }

    @Test
    void imitatorsLearnFromSimulatedTeachersAndPlay() throws IOException {
        assertEquals(0, run("simulate", "--teams", "krislet:2,krislet:2", "--cycles", "600", "--out-dir",
                dir.resolve("logs")), err.toString());
        Path scenes = dir.resolve("teal1.json.gz");
        assertEquals(0, run("convert", dir.resolve("logs/Teal_1.lsf.gz"), "-o", scenes), err.toString());
        assertEquals(0, run("play", scenes, "--metric", "ball-goal", "--players", "2", "--opponent", "krislet:2",
                "--cycles", "300", "--out-dir", dir.resolve("play")), err.toString());
        String summary = out.toString();
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
        assertTrue(err.toString().contains("one configuration"), err.toString());
    }
}
