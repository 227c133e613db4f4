package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.teacher.Teachers;

class EvaluationTest {
    private static final GameSetup.Team TEACHER = new GameSetup.Team("Teal", 3, Teachers.byName("krislet"));
    private static final GameSetup.Team OPPONENT = new GameSetup.Team("Amber", 3, Teachers.byName("krislet"));

    @Test
    void theTeacherImitatingItselfIsIndistinguishable() throws IOException {
        Evaluation.Plan plan = new Evaluation.Plan(TEACHER, Teachers.byName("krislet"), OPPONENT, 600, List.of(1L, 2L));
        Evaluation.Results results = Evaluation.run(plan, Arena.embedded(), done -> { });
        Comparison comparison = Comparison.of(results);
        // the same brains in the same seats and seeds: the same games
        for (int i = 0; i < 2; i++) {
            assertEquals(results.teacher().get(i).result(), results.imitator().get(i).result());
        }
        assertEquals(0, comparison.divergence().mean(), 1e-12);
        assertEquals(1.0, comparison.figure("agreement").imitator().mean(), 1e-12);
        assertTrue(Double.isNaN(comparison.figure("agreement").teacher().mean()), "no shadow beside the teacher");
        assertEquals(0.5, comparison.turing().accuracy(), 1e-9);
        assertEquals(comparison.figure("goalsPer1000").teacher(), comparison.figure("goalsPer1000").imitator());
        assertTrue(comparison.turing().teacherWindows() > 10);
        // the figures of the game log too, from the simulator's frames: the same for both
        assertEquals(0, comparison.executedDivergence().mean(), 1e-12);
        for (String key : List.of("executedDash", "bodyPerStep", "nearBall", "onPitch", "kickOffsTaken", "logStuckShare")) {
            assertEquals(comparison.figure(key).teacher(), comparison.figure(key).imitator(), key);
        }
        double dash = comparison.figure("executedDash").teacher().mean();
        assertTrue(dash > 0.3 && dash < 1, "executed dash share " + dash);
    }

    @Test
    void anImitatorLearntFromTheTeachersGamesMostlyAgreesWithIt() throws IOException {
        PluginRegistry registry = PluginRegistry.load();
        MatchConfig config = MatchConfig.DEFAULT.withMetric("ball-goal", java.util.Map.of());
        Learner.Imitator imitator = Learner.fromTeacherGames(TEACHER, OPPONENT, 1500, List.of(101L),
                Learner.Matching.of(config, registry), done -> { });
        assertTrue(imitator.scenes() > 1000, "scenes learnt: " + imitator.scenes());
        Evaluation.Plan plan = new Evaluation.Plan(TEACHER, imitator.brains(), OPPONENT, 800, List.of(1L, 2L));
        Comparison comparison = Comparison.of(Evaluation.run(plan, Arena.embedded(), done -> { }));
        double agreement = comparison.figure("agreement").imitator().mean();
        assertTrue(agreement > 0.6 && agreement <= 1, "agreement " + agreement);
        assertTrue(comparison.divergence().mean() < 0.2, "divergence " + comparison.divergence().mean());
        double turing = comparison.turing().accuracy();
        assertTrue(turing >= 0 && turing <= 1);
    }

    @Test
    void disjointMixesDivergeByOneBit() {
        assertEquals(1.0, Comparison.jensenShannon(new double[] {1, 0, 0}, new double[] {0, 1, 0}), 1e-12);
        assertEquals(0.0, Comparison.jensenShannon(new double[] {0.5, 0.5, 0}, new double[] {0.5, 0.5, 0}), 1e-12);
    }
}
