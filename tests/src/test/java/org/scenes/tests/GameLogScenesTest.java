package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneComparison;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.internal.vision.Fading;
import org.scenes.simulator.Engine;
import org.scenes.simulator.GameRecorder;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Seat;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * Scenes rebuilt from the server's logs of a simulated game against the scenes of the players'
 * own logs of the same game: the simulator's vision is the model the rebuilding uses, so they
 * agree up to the game log's precision (positions to 0.1 mm, angles to 0.001 degree).
 */
class GameLogScenesTest {
    private static final int CYCLES = 1000;

    @TempDir
    Path dir;

    @Test
    void rebuiltScenesMatchTheLoggedOnes() throws IOException {
        Path logs = dir.resolve("logs");
        Simulator simulator = krisletGame(logs);
        SceneComparison.Result r = compare(simulator.recorded().get(0), simulator.recorded().get(1), logs);
        // The logged scenes of the steps the game log skips (the 100 before each half's kick-off)
        // have no show to be rebuilt from; the rest pair by cycle.
        assertTrue(r.paired() > 0.97 * r.scenesA(), r.paired() + " of " + r.scenesA());
        assertTrue(r.paired() > 0.99 * r.scenesB(), r.paired() + " of " + r.scenesB());
        assertTrue(r.matchedShare() >= 0.99, "objects in both " + r.matchedShare());
        assertTrue(r.distanceWithinStepShare() >= 0.99, "distances " + r.distanceWithinStepShare());
        assertTrue(r.directionWithinStepShare() >= 0.99, "directions " + r.directionWithinStepShare());
        assertTrue(r.actionShare() >= 0.99, "actions " + r.actionShare());
    }

    /**
     * Krislet sends a command every other cycle whatever it sees, so the timing of its commands
     * tells nothing of its see clock; what it did does. The command log is made to say that every
     * player connected in step 3, as rcssserver logs it: the counter's first tick is then one of
     * three, and the true clock (the simulator's) is the third, which the first tick's misses on
     * two steps in three.
     */
    @Test
    void theSeeClockOfAPlayerOnAClockOfItsOwnIsFoundFromWhatItDid() throws IOException {
        Path logs = dir.resolve("logs");
        Simulator simulator = krisletGame(logs);
        Path rcl = simulator.recorded().get(1);
        List<String> lines = new ArrayList<>(Files.readAllLines(rcl));
        List<String> inits = new ArrayList<>();
        lines.removeIf(line -> line.contains(": (init ") && inits.add(line.replace("0,0\t", "0,3\t")));
        int at = 0;
        while (lines.get(at).startsWith("0,0\t") || lines.get(at).startsWith("0,1\t")
                || lines.get(at).startsWith("0,2\t")) {
            at++;
        }
        lines.addAll(at, inits);
        Path moved = Files.write(dir.resolve("moved.rcl"), lines);
        SceneComparison.Result r = compare(simulator.recorded().get(0), moved, logs);
        assertTrue(r.paired() > 0.99 * r.scenesB(), r.paired() + " of " + r.scenesB());
        assertTrue(r.matchedShare() >= 0.99, "objects in both " + r.matchedShare());
    }

    /** A 4 v 4 Krislet game, each player's log in {@code logs} and the server's logs in the test's directory. */
    private Simulator krisletGame(Path logs) throws IOException {
        // a team name with '_': the command log's number follows the last one
        Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Red_A", 4, Teachers.byName("krislet")),
                new GameSetup.Team("Blue", 4, Teachers.byName("krislet")), CYCLES, 3, logs)).recordTo(dir);
        simulator.run(t -> { });
        return simulator;
    }

    /** The players' logged scenes against those rebuilt from the server's logs. */
    private SceneComparison.Result compare(Path rcg, Path rcl, Path logs) throws IOException {
        Path logged = Files.createDirectories(dir.resolve("logged"));
        Path rebuilt = Files.createDirectories(dir.resolve("rebuilt"));
        List<SceneFileWriter> writers = new ArrayList<>();
        GameLogConverter.Result result = new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY,
                GameLogConverter.everyone(), 2).convert(rcg, rcl, observer -> {
                    SceneFileWriter writer = SceneFileWriter.create(rebuilt.resolve(observer.team() + "_"
                            + observer.uniformNumber() + ".json"), SceneFileHeader.of(Grid.DEFAULT,
                            new SceneSource("game", observer)));
                    writers.add(writer);
                    return writer::write;
                });
        for (SceneFileWriter writer : writers) {
            writer.commit();
        }
        assertEquals(8, result.players().size());
        assertEquals(List.of(), result.warnings());
        List<Path> left = new ArrayList<>();
        List<Path> right = new ArrayList<>();
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).build();
        for (GameLogConverter.PlayerResult player : result.players()) {
            Path log = logs.resolve(player.key() + ".lsf.gz");
            Path scenes = logged.resolve(player.key() + ".json");
            try (SceneFileWriter writer = SceneFileWriter.create(scenes, SceneFileHeader.of(Grid.DEFAULT,
                    new SceneSource("log", player.observer())))) {
                converter.convert(log, writer::write);
                writer.commit();
            }
            left.add(scenes);
            right.add(rebuilt.resolve(player.key() + ".json"));
        }
        return new SceneComparison().compare(left, right);
    }

    /**
     * Synchronous clients (version 18) that change their view width at random cycles, odd ones
     * too, on the simulator: which steps get a see depends on every earlier change (rcssserver's
     * counter), and the rebuilt scenes have their sees on the same cycles as the logged ones,
     * through the half-time break the game log skips.
     */
    @Test
    void synchronousSeesFollowEveryChangeOfViewWidth() throws Exception {
        int cycles = 300;
        Engine engine = new Engine(cycles, 5);
        Random random = new Random(5);
        Map<String, List<String>> traffic = new TreeMap<>();
        Map<Seat, List<String>> bySeat = new HashMap<>();
        List<Path> recorded;
        int changes = 0;
        try (GameRecorder recorder = GameRecorder.open(dir, engine)) {
            engine.record(recorder);
            for (String team : List.of("Red", "Blue")) {
                for (int unum = 1; unum <= 2; unum++) {
                    List<String> log = new ArrayList<>();
                    String init = "(init " + team + " (version 18))";
                    log.add(init);
                    Seat seat = engine.join(team, 18, false, init, log::add);
                    engine.welcome(seat);
                    log.add("(synch_see)");
                    engine.answerNow(seat, "(synch_see)");
                    traffic.put(team + "_" + unum, log);
                    bySeat.put(seat, log);
                }
            }
            String[] widths = {"narrow", "normal", "wide"};
            while (engine.sense()) {
                // each player answers the cycle's sees: a body command, now and then a change of width
                for (Seat seat : engine.seats()) {
                    List<String> log = bySeat.get(seat);
                    List<String> commands = new ArrayList<>(List.of(random.nextBoolean()
                            ? "(turn " + (random.nextInt(90) - 45) + ")" : "(dash " + (20 + random.nextInt(80)) + ")"));
                    if (random.nextInt(6) == 0) {
                        commands.add("(change_view " + widths[random.nextInt(3)] + ")");
                        changes++;
                    }
                    for (String command : commands) {
                        log.add(command);
                        engine.received(seat, command);
                    }
                }
                engine.advance();
            }
            recorded = recorder.commit();
        }
        assertTrue(changes > 100, changes + " changes of width");
        Map<String, Map<Integer, Integer>> logged = new TreeMap<>();
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).build();
        for (Map.Entry<String, List<String>> player : traffic.entrySet()) {
            Path log = Files.write(dir.resolve(player.getKey() + ".lsf"), player.getValue());
            Map<Integer, Integer> ages = new TreeMap<>();
            converter.convert(log, scene -> ages.put(scene.cycle(), scene.seeAge()));
            logged.put(player.getKey(), ages);
        }
        Map<String, Map<Integer, Integer>> rebuilt = new TreeMap<>();
        new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY, GameLogConverter.everyone(), 1)
                .convert(recorded.get(0), recorded.get(1), observer -> {
                    Map<Integer, Integer> ages = new TreeMap<>();
                    rebuilt.put(observer.team() + "_" + observer.uniformNumber(), ages);
                    return scene -> ages.put(scene.cycle(), scene.seeAge());
                });
        assertEquals(logged.keySet(), rebuilt.keySet());
        for (String player : logged.keySet()) {
            // the last step of each cycle has a see in both, or in neither; not compared: the kick-off
            // cycles, where a see the same as the last one (the clock stands) opens no scene of its own
            Map<Integer, Integer> rebuiltAges = rebuilt.get(player);
            List<Integer> seen = new ArrayList<>();
            List<Integer> seenRebuilt = new ArrayList<>();
            logged.get(player).forEach((cycle, age) -> {
                if (rebuiltAges.containsKey(cycle) && cycle != 0 && cycle != cycles / 2) {
                    (age == 0 ? seen : new ArrayList<Integer>()).add(cycle);
                    (rebuiltAges.get(cycle) == 0 ? seenRebuilt : new ArrayList<Integer>()).add(cycle);
                }
            });
            assertTrue(seen.size() > cycles / 3, player + ": " + seen.size() + " cycles with a see");
            assertEquals(seen, seenRebuilt, player);
        }
    }
}
