package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.SceneConverter;

/** The simulator's logs go through core's converter unchanged, like recorded games. */
class ConvertSimulatedGameTest {
    @TempDir
    Path directory;

    @Test
    void simulatedLogsConvertWithoutMalformedLines() throws IOException {
        int cycles = 2000;
        GameResult game = new Simulator(SimulatorTest.krisletGame(5, cycles, 11, directory)).run(t -> { });
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).build();
        Map<ActionType, Integer> actions = new EnumMap<>(ActionType.class);
        List<Scene> scenes = new ArrayList<>();
        ConversionReport total = new ConversionReport();
        for (Path log : game.logs()) {
            total.add(converter.convert(log, scene -> {
                scenes.add(scene);
                for (Action action : scene.actions()) {
                    actions.merge(action.type(), 1, Integer::sum);
                }
            }));
        }
        assertEquals(0, total.malformed());
        assertEquals(Map.of(), total.unknown());
        // A see on two steps of three, a Krislet command every second step: about half a scene
        // per cycle and player, and a quarter of the sees without an action, as in recorded games.
        long perPlayer = total.scenes() / game.logs().size();
        assertTrue(perPlayer > cycles * 0.4 && perPlayer < cycles * 0.7, "scenes per player " + perPlayer);
        double unanswered = (double) total.dropped(org.scenes.internal.convert.DropReason.NO_ACTION)
                / (total.scenes() + total.dropped(org.scenes.internal.convert.DropReason.NO_ACTION));
        assertEquals(0.25, unanswered, 0.03);
        assertTrue(actions.getOrDefault(ActionType.DASH, 0) > 1000, actions.toString());
        assertTrue(actions.getOrDefault(ActionType.TURN, 0) > 1000, actions.toString());
        assertTrue(actions.getOrDefault(ActionType.KICK, 0) > 10, actions.toString());
        // Each player's opening move comes before its first see, so it is counted but not kept; it
        // is sent again at the two cycle starts after each goal and after half time, as the live
        // runtime sends it, and those follow sees.
        int pauses = game.scoreLeft() + game.scoreRight() + 1;
        assertEquals(game.logs().size() * (1 + 2 * pauses), total.commands(org.scenes.internal.protocol.CommandType.MOVE));
        assertTrue(actions.getOrDefault(ActionType.MOVE, 0) <= game.logs().size() * 2 * pauses, actions.toString());
        // Teammates and opponents are told apart by the converter from the quoted team names.
        boolean teammate = false;
        boolean opponent = false;
        for (Scene scene : scenes) {
            for (SeenObject object : scene.objects()) {
                teammate |= object.relation() == Relation.TEAMMATE;
                opponent |= object.relation() == Relation.OPPONENT && object.kind() == org.scenes.api.ObjectKind.PLAYER;
            }
        }
        assertTrue(teammate && opponent);
    }

    @Test
    void stateBasedTeachersLogsConvertToo() throws IOException {
        GameResult game = new Simulator(new GameSetup(
                new GameSetup.Team("Teal", 3, org.scenes.simulator.teacher.Teachers.byName("statebased")),
                new GameSetup.Team("Amber", 3, org.scenes.simulator.teacher.Teachers.byName("krislet")), 1500, 2, directory))
                .run(t -> { });
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).build();
        Map<ActionType, Integer> actions = new EnumMap<>(ActionType.class);
        ConversionReport report = converter.convert(game.logs().get(0), scene -> {
            for (Action action : scene.actions()) {
                actions.merge(action.type(), 1, Integer::sum);
            }
        });
        assertEquals(0, report.malformed());
        assertTrue(report.scenes() > 750, "scenes " + report.scenes());
        assertTrue(actions.getOrDefault(ActionType.DASH, 0) > 0 && actions.getOrDefault(ActionType.TURN, 0) > 0,
                actions.toString());
        assertTrue(game.kicksLeft() > 0, game.toString());
    }
}
