package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;
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

    @Test
    void tracesAndShadowsGoByTheNumberTheServerGivesInWhateverOrderItsAnswersCome() {
        List<PlayerTrace> traces = new ArrayList<>();
        // a shadow that turns by a number drawn from its random source: which seed it got shows
        BrainFactory shadows = (team, random) -> {
            int moment = random.nextInt(180);
            return (message, send) -> {
                if (message.startsWith("(see ")) {
                    send.accept("(turn " + moment + ")");
                }
            };
        };
        BrainFactory traced = Evaluation.traced((team, random) -> (message, send) -> { }, shadows, 5, traces);
        Brain first = traced.create("Teal", new Random(1));
        Brain second = traced.create("Teal", new Random(2));
        // as on a live server under load: the brain made second has its answer handled first, as number 1
        second.receive("(init l 1 before_kick_off)", command -> { });
        first.receive("(init l 2 before_kick_off)", command -> { });
        first.receive("(see 0 ((b) 10 0))", command -> { });
        second.receive("(see 0 ((b) 20 0))", command -> { });
        assertEquals(List.of(1, 2), traces.stream().map(PlayerTrace::unum).toList());
        for (int unum = 1; unum <= 2; unum++) {
            PlayerTrace.Decision decision = traces.get(unum - 1).decisions().get(0);
            assertEquals(new Random(5 * 31 + unum).nextInt(180), decision.shadow().first(), 1e-9,
                    "number " + unum + "'s shadow is seeded as number " + unum + "'s in process");
        }
        assertEquals(TracedBrain.viewKey((org.scenes.internal.protocol.See)
                new org.scenes.internal.protocol.MessageParser().parse("(see 0 ((b) 20 0))")),
                traces.get(0).decisions().get(0).viewKey(), "number 1's trace holds number 1's sees");
    }
}
