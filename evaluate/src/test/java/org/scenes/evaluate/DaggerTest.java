package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameSetup;
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
        Dagger dagger = new Dagger(plan, imitator.knowledge(), matching, 0);
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
}
