package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.files.Inputs;
import org.scenes.simulator.teacher.Teachers;

class SimulatorTest {
    @TempDir
    Path directory;

    static GameSetup krisletGame(int players, int cycles, long seed, Path logs) {
        return new GameSetup(new GameSetup.Team("Teal", players, Teachers.byName("krislet")),
                new GameSetup.Team("Amber", players, Teachers.byName("krislet")), cycles, seed, logs);
    }

    private static List<String> lines(Path log) throws IOException {
        try (InputStream in = Inputs.open(log)) {
            return new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).lines().toList();
        }
    }

    @Test
    void sameSeedSameGameByteForByte() throws IOException {
        GameResult first = new Simulator(krisletGame(3, 600, 7, directory.resolve("a"))).run(t -> { });
        GameResult second = new Simulator(krisletGame(3, 600, 7, directory.resolve("b"))).run(t -> { });
        GameResult other = new Simulator(krisletGame(3, 600, 8, directory.resolve("c"))).run(t -> { });
        assertEquals(6, first.logs().size());
        boolean anyDifferent = false;
        for (int i = 0; i < first.logs().size(); i++) {
            assertArrayEquals(lines(first.logs().get(i)).toArray(), lines(second.logs().get(i)).toArray());
            anyDifferent |= !lines(first.logs().get(i)).equals(lines(other.logs().get(i)));
        }
        assertTrue(anyDifferent, "another seed plays another game");
    }

    @Test
    void logStartsLikeAClassicLsf() throws IOException {
        GameResult result = new Simulator(krisletGame(2, 100, 1, directory)).run(t -> { });
        List<String> right = lines(directory.resolve("Amber_2.lsf.gz"));
        assertEquals("(init Amber (version 9))", right.get(0));
        assertEquals("(init r 2 before_kick_off)", right.get(1));
        assertTrue(right.get(2).startsWith("(server_param ("));
        assertTrue(right.get(3).startsWith("(player_param ("));
        assertTrue(right.get(4).startsWith("(player_type (id 0)"));
        assertTrue(right.get(5).startsWith("(move "));
        assertTrue(right.contains("(hear 0 referee kick_off_l)"));
        assertEquals("(hear 100 referee time_over)", right.stream().filter(l -> l.startsWith("(hear"))
                .reduce((a, b) -> b).orElseThrow());
        assertEquals(100, result.cycles());
    }

    @Test
    void seesArriveOnTwoStepsOfThree() throws IOException {
        new Simulator(krisletGame(1, 300, 1, directory)).run(t -> { });
        List<String> log = lines(directory.resolve("Teal_1.lsf.gz"));
        long senses = log.stream().filter(l -> l.startsWith("(sense_body")).count();
        long sees = log.stream().filter(l -> l.startsWith("(see")).count();
        // the last step only announces time over, without a see
        assertEquals(2.0 / 3, (double) sees / (senses - 1), 0.01);
    }

    @Test
    void aGameHasGoalsHalfTimeAndKicks() throws IOException {
        GameResult result = new Simulator(krisletGame(5, 3000, 1, directory)).run(t -> { });
        List<String> log = lines(directory.resolve("Teal_1.lsf.gz"));
        assertTrue(log.contains("(hear 1500 referee half_time)"));
        assertTrue(log.contains("(hear 1500 referee kick_off_r)"));
        assertTrue(result.kicksLeft() > 0 && result.kicksRight() > 0, result.toString());
        assertTrue(result.scoreLeft() + result.scoreRight() > 0, result.toString());
        assertTrue(log.stream().anyMatch(l -> l.startsWith("(hear") && l.contains("goal_")));
    }

    @Test
    void noLogsAppearWhenABrainFails() {
        GameSetup setup = new GameSetup(new GameSetup.Team("Teal", 1, (team, random) -> (message, send) -> {
            if (message.startsWith("(see")) {
                throw new IllegalStateException("brain broke");
            }
        }), new GameSetup.Team("Amber", 1, Teachers.byName("krislet")), 100, 1, directory);
        assertThrows(IllegalStateException.class, () -> new Simulator(setup).run(t -> { }));
        assertFalse(Files.exists(directory.resolve("Teal_1.lsf.gz")));
        assertEquals(List.of(), listing(directory));
    }

    private static List<Path> listing(Path directory) {
        try (var files = Files.list(directory)) {
            return files.toList();
        } catch (IOException e) {
            return new ArrayList<>();
        }
    }

    @Test
    void badCommandsGetErrorsAndOnlyOneBodyCommandPerCycleCounts() throws IOException {
        GameSetup setup = new GameSetup(new GameSetup.Team("Teal", 1, (team, random) -> (message, send) -> {
            if (message.startsWith("(see 0 ")) {
                send.accept("(dash)");
                send.accept("(fly 3)");
            } else if (message.startsWith("(see")) {
                send.accept("(turn 10)");
                send.accept("(turn 10)");
            }
        }), new GameSetup.Team("Amber", 1, Teachers.byName("krislet")), 60, 1, directory);
        new Simulator(setup).run(t -> { });
        List<String> log = lines(directory.resolve("Teal_1.lsf.gz"));
        // as rcssserver answers both an ill-formed and an unknown command (its parser fails on either):
        // two errors for each see at time 0 (before kick-off the clock stands at 0)
        long seesAtZero = log.stream().filter(l -> l.startsWith("(see 0 ")).count();
        assertTrue(seesAtZero > 1);
        assertEquals(2 * seesAtZero, log.stream().filter(l -> l.equals("(error illegal_command_form)")).count());
        long turnsSent = log.stream().filter(l -> l.equals("(turn 10)")).count();
        String lastSense = log.stream().filter(l -> l.startsWith("(sense_body")).reduce((a, b) -> b).orElseThrow();
        // two turns per see, one executed per cycle
        assertTrue(lastSense.contains("(turn " + turnsSent / 2 + ")"), lastSense + " after " + turnsSent);
    }

    @Test
    void setupRejectsBadTeams() {
        assertThrows(IllegalArgumentException.class, () -> new GameSetup.Team("Teal", 12, Teachers.byName("krislet")));
        assertThrows(IllegalArgumentException.class, () -> new GameSetup.Team("has space", 1, Teachers.byName("krislet")));
        assertThrows(IllegalArgumentException.class, () -> Teachers.byName("nobody"));
    }
}
