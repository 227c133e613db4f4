package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.gamelog.PlayerState;

class GameRecordingTest {
    private static final Pattern RCL = Pattern.compile("(\\d+),(\\d+)\t(Recv (\\w+)_(\\d+): (.*)|\\(referee (\\w+)\\))");

    @TempDir
    Path directory;

    private static List<String> lines(Path file) throws IOException {
        try (InputStream in = Inputs.open(file)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
        }
    }

    @Test
    void aSimulatedGameIsRecordedAsTheServerRecordsIt() throws IOException {
        Simulator simulator = new Simulator(SimulatorTest.krisletGame(3, 1000, 4, directory.resolve("players")))
                .recordTo(directory.resolve("server"));
        List<GameFrame> emitted = new ArrayList<>();
        GameResult result = simulator.run(t -> { }, emitted::add);
        List<Path> recorded = simulator.recorded();
        String name = "Teal_" + result.scoreLeft() + "-vs-Amber_" + result.scoreRight();
        assertEquals(List.of(directory.resolve("server/" + name + ".rcg"), directory.resolve("server/" + name + ".rcl")),
                recorded);

        // The game log: every frame after kick-off, as the reader gives them back.
        List<GameFrame> read = GameLogReader.readAll(recorded.get(0));
        List<GameFrame> expected = emitted.stream().filter(f -> !f.playMode().equals("before_kick_off")
                && !f.playMode().equals("half_time")).toList();
        int timeOver = (int) expected.stream().takeWhile(f -> !f.playMode().equals("time_over")).count();
        expected = expected.subList(0, timeOver + 1);
        assertEquals(expected.size(), read.size());
        for (int i = 0; i < read.size(); i++) {
            GameFrame e = expected.get(i);
            GameFrame r = read.get(i);
            assertEquals(e.time(), r.time());
            assertEquals(e.scoreLeft(), r.scoreLeft());
            assertEquals(e.ball().x(), r.ball().x(), 5e-5);
            for (int p = 0; p < 6; p++) {
                PlayerState ep = e.players().get(p);
                PlayerState rp = r.players().get(p);
                assertEquals(ep.y(), rp.y(), 5e-5);
                assertEquals(ep.counts(), rp.counts());
            }
        }
        GameFrame last = read.get(read.size() - 1);
        assertEquals("time_over", last.playMode());
        assertEquals(result.scoreLeft(), last.scoreLeft());
        assertEquals(result.scoreRight(), last.scoreRight());

        // The command log: every message each client sent, in the order of its player log.
        List<String> commandLog = lines(recorded.get(1));
        List<String> teal2 = new ArrayList<>();
        int referee = 0;
        for (String line : commandLog) {
            Matcher m = RCL.matcher(line);
            assertTrue(m.matches(), line);
            if (m.group(7) != null) {
                referee++;
            } else if (m.group(4).equals("Teal") && m.group(5).equals("2")) {
                teal2.add(m.group(6));
            }
        }
        assertTrue(referee > 3, "kick-off, half time, time over and more");
        List<String> sent = lines(directory.resolve("players/Teal_2.lsf.gz")).stream()
                .filter(l -> l.startsWith("(init Teal") || l.startsWith("(dash") || l.startsWith("(turn")
                        || l.startsWith("(kick") || l.startsWith("(move"))
                .toList();
        assertEquals(sent, teal2);
        assertTrue(commandLog.contains("0,0\tRecv Teal_1: (init Teal (version 9))"));
        assertTrue(commandLog.contains("500,0\t(referee half_time)"), "half time at 500");
        assertEquals("1000,0\t(referee time_over)", commandLog.get(commandLog.size() - 1));
        assertTrue(Files.list(directory.resolve("server")).count() == 2, "no temporary files left");
    }
}
