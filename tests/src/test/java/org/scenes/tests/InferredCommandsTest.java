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
import org.scenes.api.Grid;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.GameSceneFiles;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneComparison;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.inference.CommandCheck;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.vision.Fading;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * The commands inferred from a simulated game's log alone against its command log (the
 * simulator's, the truth), and the scenes built from each.
 */
class InferredCommandsTest {
    @TempDir
    Path dir;

    private Simulator game(String teacher, int cycles) throws IOException {
        Simulator simulator = new Simulator(new GameSetup(new GameSetup.Team("Red", 4, Teachers.byName(teacher)),
                new GameSetup.Team("Blue", 4, Teachers.byName(teacher)), cycles, 7, dir.resolve("logs")))
                .recordTo(dir.resolve("server"));
        simulator.run(t -> { });
        return simulator;
    }

    @Test
    void theInferredCommandsAgreeWithTheCommandLog() throws IOException {
        // statebased players kick more than Krislet's
        Simulator simulator = game("statebased", 1000);
        CommandCheck.Result r = CommandCheck.check(simulator.recorded().get(0), simulator.recorded().get(1));
        assertTrue(r.executed() > 2000, r.table());
        assertTrue(r.byType().getOrDefault(CommandType.KICK, 0L) >= 10, r.table());
        assertTrue(r.byType().getOrDefault(CommandType.TURN, 0L) > 300, r.table());
        assertTrue(r.agreement() >= 0.995, r.table());
        assertTrue(r.turnMedian() <= 2, r.table());
        assertTrue(r.dashPowerWithin5() >= 0.95, r.table());
        assertTrue(r.kickDirectionWithin5() >= 0.90, r.table());
    }

    /** The same from the other forms rcssserver writes its game log in: text versions 4 and 5, and JSON. */
    @Test
    void theInferredCommandsAgreeInEveryFormOfTheGameLog() throws IOException {
        Simulator simulator = game("statebased", 1000);
        Path rcl = simulator.recorded().get(1);
        CommandCheck.Result six = CommandCheck.check(simulator.recorded().get(0), rcl);
        for (String version : List.of("4", "5", "json")) {
            Path rewritten = GameLogVersions.rewrite(simulator.recorded().get(0), version,
                    dir.resolve("game-" + version + ".rcg"));
            String head = Files.readString(rewritten).substring(0, 4);
            assertEquals(version.equals("json") ? "[{\"v" : "ULG" + version, head, "the log is in the form asked");
            CommandCheck.Result r = CommandCheck.check(rewritten, rcl);
            String what = "version " + version + ":\n" + r.table();
            assertEquals(six.executed(), r.executed(), what);
            assertEquals(six.byType(), r.byType(), what);
            assertTrue(r.agreement() >= 0.995, what);
            assertTrue(r.turnMedian() <= 2, what);
            assertTrue(r.dashPowerWithin5() >= 0.95, what);
            assertTrue(r.kickDirectionWithin5() >= 0.90, what);
        }
    }

    /**
     * The scenes of the cycles both conversions have carry the same actions and see the same. The
     * game log does not show the steps before kick-off (the command log's referee counts them): an
     * asynchronous player's see clock, counted in steps, may then have another phase, so about a
     * third of the cycles differ; checked here, the cycles in common.
     */
    @Test
    void scenesFromTheGameLogAloneHaveTheActionsOfThoseWithItsCommandLog() throws IOException {
        Simulator simulator = game("krislet", 600);
        Path rcg = simulator.recorded().get(0);
        GameLogs withCommands = GameLogs.among(List.of(rcg), GameLogs.Commands.RCL);
        Path alone = Files.copy(rcg, Files.createDirectories(dir.resolve("alone")).resolve("game.rcg"));
        GameLogs inferred = GameLogs.among(List.of(alone), GameLogs.Commands.AUTO);
        assertTrue(inferred.inferred(), "no command log beside: inferred");
        List<Path> a = convert(withCommands, dir.resolve("rcl"));
        List<Path> b = convert(inferred, dir.resolve("infer"));
        assertEquals(8, b.size());
        SceneComparison.Result r = new SceneComparison().compare(a, b);
        assertTrue(r.scenesB() >= 0.98 * r.scenesA(), r.scenesB() + " of " + r.scenesA());
        assertTrue(r.paired() >= 0.5 * r.scenesA(), r.paired() + " of " + r.scenesA());
        assertTrue(r.actionTypeShare() >= 0.99, "action types " + r.actionTypeShare());
        assertTrue(r.matchedShare() >= 0.99, "objects in both " + r.matchedShare());
    }

    private List<Path> convert(GameLogs logs, Path out) throws IOException {
        Files.createDirectories(out);
        return new ArrayList<>(GameSceneFiles.write(new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY,
                GameLogConverter.everyone(), 1), Grid.DEFAULT, logs, key -> out.resolve(key + ".json")).files());
    }

}
