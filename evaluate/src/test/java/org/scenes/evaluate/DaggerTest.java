package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.api.Grid;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

class DaggerTest {
    private static final GameSetup.Team TEACHER = new GameSetup.Team("Teal", 2, Teachers.byName("krislet"));
    private static final GameSetup.Team OPPONENT = new GameSetup.Team("Amber", 2, Teachers.byName("krislet"));

    @Test
    void aRoundAddsTheImitatorsScenesLabelledWithTheShadowsCommands() throws IOException {
        Learner.Matching matching = Learner.Matching.of(MatchConfig.DEFAULT.withMetric("ball-goal", java.util.Map.of()),
                PluginRegistry.load());
        Learner.Imitator imitator = Learner.fromTeacherGames(TEACHER, OPPONENT, 300, List.of(101L), matching,
                done -> { });
        Evaluation.Plan plan = new Evaluation.Plan(TEACHER, imitator.brains(), OPPONENT, 300, List.of(1L));
        Dagger dagger = new Dagger(plan, imitator, 0);
        assertEquals(600, dagger.nextRoundCycles(), "the first round plays the teacher's games too");
        Dagger.Round first = dagger.next(Arena.embedded(), done -> { });

        // labelling changes nothing in the play: the same games as a plain evaluation
        Evaluation.Results plain = Evaluation.run(plan, Arena.embedded(), done -> { });
        assertEquals(plain.imitator().get(0).result(), first.results().imitator().get(0).result());
        assertEquals(plain.teacher().get(0).result(), first.results().teacher().get(0).result());

        // per player, the labels are the shadow's first body commands on the sees it answered, in order
        List<List<Scene>> corrections = dagger.corrections();
        List<PlayerTrace> traces = first.results().imitator().get(0).traces();
        assertEquals(2, corrections.size());
        for (int player = 0; player < 2; player++) {
            List<PlayerTrace.Decision> answered = traces.get(player).decisions().stream()
                    .filter(d -> d.shadow() != null).toList();
            List<Scene> labelled = corrections.get(player);
            assertTrue(labelled.size() > 50, "labelled scenes: " + labelled.size());
            assertEquals(answered.stream().map(d -> d.shadow().toAction()).toList(),
                    labelled.stream().map(Scene::primaryAction).toList());
            assertEquals(answered.stream().map(PlayerTrace.Decision::time).toList(),
                    labelled.stream().map(Scene::cycle).toList());
            // and not what the imitator itself did on those sees
            long differing = answered.stream().filter(d -> !Objects.equals(d.driver(), d.shadow())).count();
            assertTrue(differing > 0, "the imitator never parted from its shadow");
        }
        for (int player = 0; player < 2; player++) {
            int unum = player + 1;
            assertTrue(corrections.get(player).stream().allMatch(scene -> scene.observer().uniformNumber() == unum),
                    "player " + unum + "'s labels are its own scenes");
        }
        int labelled = corrections.stream().mapToInt(List::size).sum();
        assertEquals(labelled, first.labelled());

        assertEquals(300, dagger.nextRoundCycles(), "the teacher's games are played once");
        Dagger.Round second = dagger.next(Arena.embedded(), done -> { });
        assertEquals(first.scenes() + labelled, second.scenes());
        assertEquals(labelled, second.added());
        assertEquals(first.results().teacher(), second.results().teacher());
        assertEquals(1, second.number());
        assertTrue(second.comparison().figure("agreement").imitator().mean() > 0.3, second.row());
        assertTrue(Dagger.Round.header().startsWith("round") && second.row().startsWith("1 "), second.row());
    }

    @Test
    void withRolesEachPlayersLabelsJoinItsCounterpartsScenes(@TempDir Path directory) throws IOException {
        // the teacher's players' scene files, as 'scenes convert' writes them: a uniform number each
        GameResult game = new Simulator(new GameSetup(TEACHER, OPPONENT, 300, 101L, directory.resolve("logs"))).run(time -> { });
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).world(true).build();
        List<Path> files = new ArrayList<>();
        for (Path log : game.logs()) {
            if (log.getFileName().toString().startsWith("Teal_")) {
                List<Scene> scenes = new ArrayList<>();
                converter.convert(log, scenes::add);
                Path file = directory.resolve(log.getFileName() + ".json");
                SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT,
                        new SceneSource(log.getFileName().toString(), scenes.get(0).observer())), scenes));
                files.add(file);
            }
        }
        Learner.Matching matching = Learner.Matching.of(MatchConfig.DEFAULT.withMetric("ball-goal", java.util.Map.of()),
                PluginRegistry.load());
        Learner.Imitator imitator = Learner.roles(files, matching, ImitationTeam.Knowledge.COUNTERPART);
        assertTrue(imitator.roles().describe().startsWith("counterpart knowledge, 2 recorded players"),
                imitator.roles().describe());
        Evaluation.Plan plan = new Evaluation.Plan(TEACHER, imitator.brains(), OPPONENT, 300, List.of(1L));
        Dagger dagger = new Dagger(plan, imitator, 0);
        Dagger.Round first = dagger.next(Arena.embedded(), done -> { });
        List<List<Scene>> corrections = dagger.corrections();
        Dagger.Round second = dagger.next(Arena.embedded(), done -> { });
        assertEquals(first.scenes() + first.labelled(), second.scenes(), "the team's knowledge holds every label");
        // each counterpart's knowledge: its recorded scenes and its own player's labels, no one else's
        Learner.Imitator corrected = imitator.plus(java.util.Map.of(1, List.of(corrections.get(0)),
                2, List.of(corrections.get(1))));
        assertEquals(second.scenes(), corrected.scenes());
        assertTrue(corrections.get(0).size() > 50 && corrections.get(1).size() > 50, "labels: " + first.labelled());
    }
}
