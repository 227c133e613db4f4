package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.GameSceneFiles;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.vision.Fading;
import org.scenes.simulator.teacher.Teachers;

/** A goalie's role reaches its logs and scene files; kick-off moves are repeated only for brains that want it. */
class RolesInTheSimulatorTest {
    @TempDir
    Path directory;

    /** Krislet brains; player 1 a goalie when asked; the runtime repeats their moves when asked. */
    private static BrainFactory krislet(boolean goalie, boolean repeats) {
        BrainFactory teacher = Teachers.byName("krislet");
        return new BrainFactory() {
            @Override
            public Brain create(String team, Random random) {
                Brain inner = teacher.create(team, random);
                return new Brain() {
                    @Override
                    public void receive(String message, Consumer<String> send) {
                        inner.receive(message, send);
                    }

                    @Override
                    public boolean repeatsKickOffMove() {
                        return repeats;
                    }
                };
            }

            @Override
            public boolean goalie(int unum) {
                return goalie && unum == 1;
            }
        };
    }

    private static long count(Path log, String prefix) throws IOException {
        try (InputStream in = Inputs.open(log)) {
            return new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).lines()
                    .filter(line -> line.startsWith(prefix)).count();
        }
    }

    @Test
    void theGoalieInitsAsGoalieAndItsScenesSaySo() throws IOException {
        Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Teal", 2, krislet(true, true)),
                new GameSetup.Team("Amber", 2, Teachers.byName("krislet")), 300, 4, directory.resolve("logs")))
                .recordTo(directory.resolve("server"));
        GameResult game = simulator.run(t -> { });
        Path goalieLog = game.logs().get(0);
        assertTrue(goalieLog.getFileName().toString().startsWith("Teal_1"), goalieLog.toString());
        assertEquals(1, count(goalieLog, "(init Teal (version 9) (goalie))"));
        boolean[] told = new boolean[1];
        SceneConverter.with(Grid.DEFAULT).strict(true).build().convert(goalieLog,
                SceneConverter.SceneSink.of(scene -> { }, () -> told[0] = true));
        assertTrue(told[0], "the player log's init says goalie");

        List<Path> written = GameSceneFiles.write(new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY,
                GameLogConverter.everyone(), 1), Grid.DEFAULT, GameLogs.among(simulator.recorded()),
                key -> directory.resolve(key + ".json")).files();
        List<String> goalies = new ArrayList<>();
        for (Path file : written) {
            try (SceneFileReader reader = SceneFileReader.open(file)) {
                if (reader.header().source().goalie()) {
                    goalies.add(file.getFileName().toString());
                }
            }
        }
        assertEquals(List.of("Teal_1.json"), goalies, "the game log marks the goalie");
    }

    @Test
    void theKickOffMoveIsRepeatedAfterGoalsOnlyForBrainsThatWantIt() throws IOException {
        GameResult game = new Simulator(new GameSetup(new GameSetup.Team("Teal", 5, krislet(false, false)),
                new GameSetup.Team("Amber", 5, krislet(false, true)), 1000, 11, directory)).run(t -> { });
        assertTrue(game.scoreLeft() + game.scoreRight() > 0, "the game needs a goal to test this");
        for (Path log : game.logs()) {
            long moves = count(log, "(move ");
            if (log.getFileName().toString().startsWith("Teal_")) {
                assertEquals(1, moves, log + ": only the brain's own move");
            } else {
                assertFalse(moves == 1, log + ": the runtime repeats the move after goals");
            }
        }
    }
}
