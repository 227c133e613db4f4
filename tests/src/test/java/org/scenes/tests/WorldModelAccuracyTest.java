package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.api.Side;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.world.WorldAccuracy;
import org.scenes.simulator.Engine;
import org.scenes.simulator.GameRecorder;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Seat;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * The world model of scenes against the true positions of the game log, on a seeded simulated
 * 4 v 4 game, for each field side, by both code paths: the players' own logs and the percepts
 * rebuilt from the game log. The bounds are about twice the errors measured (docs/conversion.md).
 */
class WorldModelAccuracyTest {
    private static final int CYCLES = 1000;

    @TempDir
    Path dir;

    @Test
    void scenesPlaceThePlayerAndTheBallWithinTheServersNoise() throws IOException {
        Path logs = dir.resolve("logs");
        Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Red", 4, Teachers.byName("krislet")),
                new GameSetup.Team("Blue", 4, Teachers.byName("krislet")), CYCLES, 3, logs)).recordTo(dir);
        simulator.run(t -> { });
        Path rcg = simulator.recorded().get(0);
        Path rcl = simulator.recorded().get(1);

        Map<Side, WorldAccuracy> fromLogs = new EnumMap<>(Side.class);
        Map<Side, WorldAccuracy> fromGameLog = new EnumMap<>(Side.class);
        for (Side side : Side.values()) {
            fromLogs.put(side, new WorldAccuracy(rcg));
            fromGameLog.put(side, new WorldAccuracy(rcg));
        }
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).world(true).build();
        for (String team : new String[] {"Red", "Blue"}) {
            for (int unum = 1; unum <= 4; unum++) {
                converter.convert(logs.resolve(team + "_" + unum + ".lsf.gz"),
                        scene -> fromLogs.get(scene.observer().side()).add(scene));
            }
        }
        new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY, GameLogConverter.everyone(), 1).world(true)
                .convert(rcg, rcl, observer -> scene -> fromGameLog.get(observer.side()).add(scene));

        for (Map<Side, WorldAccuracy> path : List.of(fromLogs, fromGameLog)) {
            for (Side side : Side.values()) {
                WorldAccuracy.Report r = path.get(side).report();
                String figures = side + " " + r;
                assertTrue(r.scenes() > 4 * CYCLES * 0.2, figures);
                assertTrue(r.unlocated() == 0, figures);
                assertTrue(r.position().median() < 0.25 && r.position().p90() < 0.7, figures);
                assertTrue(r.body().median() < 1 && r.body().p90() < 1.5, figures);
                assertTrue(r.ballSeen().median() < 0.7 && r.ballSeen().p90() < 1.8, figures);
                assertTrue(r.ballVelocity().median() < 0.15, figures);
            }
        }
    }

    /**
     * Version 18 players on synchronous vision (a see every other cycle in normal view), a random
     * turn or dash every cycle, scenes per cycle: on the cycles without a see the position and body
     * are carried on by sense_body's velocity and the executed turn.
     */
    @Test
    void perCycleScenesCarryThePlayerBetweenSees() throws Exception {
        Engine engine = new Engine(600, 7);
        Random random = new Random(7);
        Map<String, List<String>> traffic = new TreeMap<>();
        Map<Seat, List<String>> bySeat = new HashMap<>();
        List<Path> recorded;
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
            while (engine.sense()) {
                for (Seat seat : engine.seats()) {
                    String command = random.nextInt(3) == 0 ? "(turn " + (random.nextInt(90) - 45) + ")"
                            : "(dash " + (20 + random.nextInt(80)) + ")";
                    bySeat.get(seat).add(command);
                    engine.received(seat, command);
                }
                engine.advance();
            }
            recorded = recorder.commit();
        }
        WorldAccuracy seen = new WorldAccuracy(recorded.get(0));
        WorldAccuracy carried = new WorldAccuracy(recorded.get(0));
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).world(true).build();
        for (Map.Entry<String, List<String>> player : traffic.entrySet()) {
            Path log = Files.write(dir.resolve(player.getKey() + ".lsf"), player.getValue());
            converter.convert(log, scene -> (scene.seeAge() == 0 ? seen : carried).add(scene));
        }
        for (WorldAccuracy accuracy : List.of(seen, carried)) {
            WorldAccuracy.Report r = accuracy.report();
            String figures = r.toString();
            assertTrue(r.scenes() > 4 * 600 * 0.3, figures);
            assertTrue(r.position().median() < 0.3 && r.position().p90() < 0.8, figures);
            assertTrue(r.body().median() < 1 && r.body().p90() < 4, figures);
        }
    }
}
