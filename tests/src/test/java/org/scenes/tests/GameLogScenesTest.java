package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.agent.sim.GameSetup;
import org.scenes.agent.sim.Simulator;
import org.scenes.agent.teacher.Teachers;
import org.scenes.api.Grid;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneComparison;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.internal.vision.Fading;

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
        // a team name with '_': the command log's number follows the last one
        Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Red_A", 4, Teachers.byName("krislet")),
                new GameSetup.Team("Blue", 4, Teachers.byName("krislet")), CYCLES, 3, logs)).recordTo(dir);
        simulator.run(t -> { });
        Path rcg = simulator.recorded().get(0);
        Path rcl = simulator.recorded().get(1);
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
        SceneConverter converter = new SceneConverter(Grid.DEFAULT, false, line -> { });
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
        SceneComparison.Result r = new SceneComparison().compare(left, right);
        // The logged scenes of the steps the game log skips (the 100 before each half's kick-off)
        // have no show to be rebuilt from; the rest pair by cycle.
        assertTrue(r.paired() > 0.97 * r.scenesA(), r.paired() + " of " + r.scenesA());
        assertTrue(r.paired() > 0.99 * r.scenesB(), r.paired() + " of " + r.scenesB());
        assertTrue(r.matchedShare() >= 0.99, "objects in both " + r.matchedShare());
        assertTrue(r.distanceWithinStepShare() >= 0.99, "distances " + r.distanceWithinStepShare());
        assertTrue(r.directionWithinStepShare() >= 0.99, "directions " + r.directionWithinStepShare());
        assertTrue(r.actionShare() >= 0.99, "actions " + r.actionShare());
    }
}
