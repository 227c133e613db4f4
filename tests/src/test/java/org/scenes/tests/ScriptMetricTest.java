package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.QueryFailure;
import org.scenes.internal.validate.ValidationReport;
import org.scenes.internal.validate.Validator;

/**
 * The shipped scripts against the built-in Java plugins they imitate, on simulated Krislet scenes:
 * same distances, same validation; and a failing script located by query and line.
 */
class ScriptMetricTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();
    private static final String SCRIPT = "script:"
            + Path.of(System.getProperty("scenes.examples", "../examples/scripts"), "ball-goal.groovy");

    static List<Scene> train;
    static List<Scene> test;

    /** Two players of a simulated Krislet game: what is compared needs no recorded game. */
    @BeforeAll
    static void convert() throws IOException {
        train = scenes(SimulatedGame.log("Carleton", 1));
        test = scenes(SimulatedGame.log("Carleton", 2));
    }

    static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build().convert(log, scenes::add);
        assertTrue(scenes.size() > 1000, log + " gave only " + scenes.size() + " scenes");
        return scenes;
    }

    @Test
    void scriptGivesTheJavaMetricsDistances() {
        for (String weights : new String[] {"1/1/1/1/0/1/1/1", "ball=2,goal=0.5"}) {
            PluginConfig config = PluginConfig.DEFAULT.withObjectWeights(ObjectWeights.parse(weights));
            SceneMetric java = REGISTRY.metric("ball-goal", config);
            SceneMetric script = REGISTRY.metric(SCRIPT, config);
            int differentFromZero = 0;
            for (int i = 0; i < test.size(); i += 7) {
                Scene query = test.get(i);
                Scene stored = train.get((i * 31) % train.size());
                double expected = java.distance(query, stored);
                assertEquals(expected, script.distance(query, stored), 1e-12, "query " + i);
                differentFromZero += expected > 0 ? 1 : 0;
            }
            assertTrue(differentFromZero > 100, "the pairs compared must differ");
        }
    }

    @Test
    void scriptValidatesLikeTheJavaMetric() {
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, train);
        List<Scene> queries = test.subList(0, 1500);
        MatchConfig java = MatchConfig.DEFAULT.withMetric("ball-goal", Map.of()).withK(3).withSelector("vote", Map.of());
        MatchConfig script = java.withMetric(SCRIPT, Map.of());
        ValidationReport expected = Validator.run(knowledge, queries, java, REGISTRY, true, null);
        ValidationReport actual = Validator.run(knowledge, queries, script, REGISTRY, true, null);
        assertEquals(expected.accuracy(), actual.accuracy());
        assertEquals(expected.macroF1(), actual.macroF1());
        assertTrue(expected.accuracy() > 0.2, "accuracy " + expected.accuracy());
    }

    @Test
    void voteScriptSelectsLikeTheBuiltInVote() {
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, train);
        List<Scene> queries = test.subList(0, 1500);
        String vote = "script:" + Path.of(System.getProperty("scenes.examples", "../examples/scripts"), "vote.groovy");
        for (String actionWeights : new String[] {"1/1/1/1/1/1/1", "1/1/3/0/1/1/1"}) {
            MatchConfig java = MatchConfig.DEFAULT.withMetric("ball-goal", Map.of()).withK(7).withSelector("vote", Map.of())
                    .withActionWeights(org.scenes.api.ActionWeights.parse(actionWeights));
            ValidationReport expected = Validator.run(knowledge, queries, java, REGISTRY, true, null);
            ValidationReport actual = Validator.run(knowledge, queries, java.withSelector(vote, Map.of()), REGISTRY, true, null);
            assertEquals(expected.accuracy(), actual.accuracy(), actionWeights);
            assertEquals(expected.directionAccuracy(), actual.directionAccuracy(), actionWeights);
        }
    }

    @Test
    void failingScriptIsLocatedByQueryAndLine(@TempDir Path dir) throws IOException {
        // the first query whose cycle no earlier query has (sees before kick-off share cycle 0)
        int first = 1;
        while (first < test.size() && cycleSeenBefore(first)) {
            first++;
        }
        int index = first;
        int cycle = test.get(index).cycle();
        Path failing = Files.writeString(dir.resolve("picky.groovy"), """
                double distance(Scene query, Scene stored) {
                    if (query.cycle() == %d) {
                        throw new IllegalStateException('cannot compare this one')
                    }
                    return Math.abs(query.objects().size() - stored.objects().size())
                }
                """.formatted(cycle));
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, train.subList(0, 50));
        MatchConfig config = MatchConfig.DEFAULT.withMetric("script:" + failing, Map.of());
        QueryFailure failure = assertThrows(QueryFailure.class,
                () -> Validator.run(knowledge, test.subList(0, index + 10), config, REGISTRY, false, null));
        assertEquals(index, failure.index());
        assertEquals("query scene " + index + " (cycle " + cycle + "): " + failing + ":3: IllegalStateException: "
                + "cannot compare this one (comparing the query scene of cycle " + cycle
                + " with the stored scene of cycle " + train.get(0).cycle() + ")", failure.getMessage());
        assertInstanceOf(org.scenes.plugins.script.ScriptFailure.class, failure.getCause());
    }

    private static boolean cycleSeenBefore(int index) {
        for (int i = 0; i < index; i++) {
            if (test.get(i).cycle() == test.get(index).cycle()) {
                return true;
            }
        }
        return false;
    }
}
