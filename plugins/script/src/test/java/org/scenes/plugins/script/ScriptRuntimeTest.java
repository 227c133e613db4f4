package org.scenes.plugins.script;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

/** How scripts run: per-instance state, configuration, and failures located in the script. */
class ScriptRuntimeTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    @TempDir
    Path dir;

    private String write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text).toString();
    }

    @Test
    void exceptionReportsScriptLineAndScenes() throws IOException {
        String path = write("thrower.groovy", """
                double distance(Scene query, Scene stored) {
                    int seen = query.objects().size()
                    return 10 / (seen - 1)
                }
                """);
        SceneMetric metric = REGISTRY.metric("script:" + path, PluginConfig.DEFAULT);
        Scene one = Fixtures.scene(57, null, Fixtures.ball(3, 0));
        Scene stored = Fixtures.scene(120, null);
        ScriptFailure failure = assertThrows(ScriptFailure.class, () -> metric.distance(one, stored));
        assertEquals(3, failure.line());
        assertEquals(path, failure.script());
        assertEquals(path + ":3: ArithmeticException: Division by zero (comparing the query scene of cycle 57 "
                + "with the stored scene of cycle 120)", failure.getMessage());
        assertInstanceOf(ArithmeticException.class, failure.getCause());
    }

    @Test
    void aCallThatNeverReturnsIsEndedAtTheTimeLimitNamingItsLine() throws IOException {
        String metricPath = write("forever.groovy", """
                double distance(Scene query, Scene stored) {
                    double sum = 0
                    while (true) {
                        sum += 1
                    }
                    return sum
                }
                """);
        String selectorPath = write("stuck.groovy", """
                Action select(List<Neighbour> nearest, RandomGenerator random) {
                    for (int i = 0; i >= 0; i = 0) { }
                    return null
                }
                """);
        java.time.Duration before = ScriptWatch.limit();
        ScriptWatch.limit(java.time.Duration.ofMillis(300));
        try {
            SceneMetric metric = REGISTRY.metric("script:" + metricPath, PluginConfig.DEFAULT);
            ScriptFailure failure = assertThrows(ScriptFailure.class,
                    () -> metric.distance(Fixtures.scene(1, null), Fixtures.scene(2, null)));
            org.junit.jupiter.api.Assertions.assertTrue(failure.getMessage().startsWith(metricPath + ":")
                    && failure.getMessage().contains("ran longer than 300 ms"), failure.getMessage());
            org.junit.jupiter.api.Assertions.assertTrue(failure.line() >= 3 && failure.line() <= 5, failure.getMessage());
            org.junit.jupiter.api.Assertions.assertFalse(Thread.currentThread().isInterrupted(), "the caller goes on");
            ActionSelector selector = REGISTRY.selector("script:" + selectorPath, PluginConfig.DEFAULT);
            Neighbour neighbour = new Neighbour(Fixtures.scene(3, Action.dash(50)), 0, 0);
            ScriptFailure stuck = assertThrows(ScriptFailure.class,
                    () -> selector.select(List.of(neighbour), new SplittableRandom(1)));
            org.junit.jupiter.api.Assertions.assertTrue(stuck.getMessage().contains("ran longer than 300 ms"), stuck.getMessage());
            // a script that returns at once is never stopped, however many calls it makes
            String quickPath = write("quick.groovy", """
                    double distance(Scene query, Scene stored) {
                        double sum = 0
                        for (int i = 0; i < 100; i++) { sum += i }
                        return sum
                    }
                    """);
            SceneMetric quick = REGISTRY.metric("script:" + quickPath, PluginConfig.DEFAULT);
            long deadline = System.nanoTime() + 1_000_000_000L;
            while (System.nanoTime() < deadline) {
                assertEquals(4950, quick.distance(Fixtures.scene(1, null), Fixtures.scene(2, null)), 0);
            }
        } finally {
            ScriptWatch.limit(before);
        }
    }

    @Test
    void exceptionInAHelperMethodReportsTheHelpersLine() throws IOException {
        String path = write("helper.groovy", """
                double distance(Scene query, Scene stored) {
                    return first(query).distance()
                }

                SeenObject first(Scene scene) {
                    if (scene.objects().isEmpty()) throw new IllegalStateException('no objects')
                    return scene.objects().get(0)
                }
                """);
        SceneMetric metric = REGISTRY.metric("script:" + path, PluginConfig.DEFAULT);
        ScriptFailure failure = assertThrows(ScriptFailure.class,
                () -> metric.distance(Fixtures.scene(1, null), Fixtures.scene(2, null)));
        assertEquals(6, failure.line());
    }

    @Test
    void selectorFailureReportsLine() throws IOException {
        String path = write("picky.groovy", """
                Action select(List<Neighbour> nearest, RandomGenerator random) {
                    assert nearest.size() > 1 : 'needs two neighbours'
                    return nearest.get(1).scene().primaryAction()
                }
                """);
        ActionSelector selector = REGISTRY.selector("script:" + path, PluginConfig.DEFAULT);
        List<Neighbour> one = List.of(new Neighbour(Fixtures.scene(9, Action.dash(50)), 0, 1.5));
        ScriptFailure failure = assertThrows(ScriptFailure.class, () -> selector.select(one, new SplittableRandom(1)));
        assertEquals(2, failure.line());
    }

    @Test
    void setUpRunsOncePerInstanceWithTheConfiguration() throws IOException {
        String path = write("counting.groovy", """
                import groovy.transform.Field

                @Field double scale
                @Field int calls

                scale = weights.ball() * 10

                double distance(Scene query, Scene stored) {
                    calls++
                    return scale * calls
                }
                """);
        PluginConfig config = PluginConfig.DEFAULT.withObjectWeights(ObjectWeights.parse("ball=2"));
        SceneMetric first = REGISTRY.metric("script:" + path, config);
        SceneMetric second = REGISTRY.metric("script:" + path, config);
        Scene scene = Fixtures.scene(1, null);
        assertEquals(20, first.distance(scene, scene));
        assertEquals(40, first.distance(scene, scene));
        // A second metric (another thread's) has its own state.
        assertEquals(20, second.distance(scene, scene));
        assertNotSame(first, second);
    }

    @Test
    void primitiveFieldsStayPrimitive() throws IOException, ReflectiveOperationException {
        String path = write("fields.groovy", """
                import groovy.transform.Field

                @Field static final double LIMIT = 2
                @Field long seen

                double distance(Scene query, Scene stored) { seen++; LIMIT }
                """);
        SceneMetric metric = REGISTRY.metric("script:" + path, PluginConfig.DEFAULT);
        Scene scene = Fixtures.scene(1, null);
        assertEquals(2, metric.distance(scene, scene));
        Class<?> compiled = ScriptCompiler.compile("metric", path, MetricScript.class);
        assertEquals(double.class, compiled.getDeclaredField("LIMIT").getType());
        assertEquals(long.class, compiled.getDeclaredField("seen").getType());
    }

    @Test
    void enumAndBooleanEqualityKeepTheirMeaningWhenCompiledAsIdentity() throws IOException {
        // == and != between enums or booleans compile to reference comparisons (FastEqualityCustomizer).
        String path = write("kinds.groovy", """
                double distance(Scene query, Scene stored) {
                    double score = 0
                    for (SeenObject object : query.objects()) {
                        if (object.kind() == ObjectKind.BALL) score += 1
                        if (object.kind() != ObjectKind.BALL) score += 10
                        if (object.relation() == stored.objects().get(0).relation()) score += 100
                        ObjectKind nothing = null
                        if (object.kind() == nothing) score += 1000
                        if (nothing == null) score += 10000
                        boolean near = object.distance() < 4
                        boolean goal = object.kind() == ObjectKind.GOAL
                        if (near == goal) score += 100000
                        if (near != goal) score += 1000000
                    }
                    return score
                }
                """);
        SceneMetric metric = REGISTRY.metric("script:" + path, PluginConfig.DEFAULT);
        Scene query = Fixtures.scene(1, null, Fixtures.ball(3, 0), Fixtures.opponentGoal(30, 2), Fixtures.flag(5, 5));
        Scene stored = Fixtures.scene(2, null, Fixtures.flag(1, 1));
        // ball: 1 + 100 (relation NONE) ; goal: 10 ; flag: 10 + 100 ; and 10000 for each of the three.
        // near != goal for the ball (near, not a goal) and the goal (far, a goal); == for the flag (far, no goal).
        assertEquals(1 + 100 + 10 + 10 + 100 + 30000 + 100000 + 2 * 1000000, metric.distance(query, stored));
    }

    @Test
    void closuresAndHelperClassesWork() throws IOException {
        String path = write("helpers.groovy", """
                class Counts {
                    static int twice(int value) { 2 * value }
                }

                double distance(Scene query, Scene stored) {
                    int balls = query.objects().count { SeenObject o -> o.kind() == ObjectKind.BALL } as int
                    if (balls > 1) throw new IllegalStateException('two balls')
                    return Counts.twice(balls) + stored.objects().size()
                }
                """);
        SceneMetric metric = REGISTRY.metric("script:" + path, PluginConfig.DEFAULT);
        Scene query = Fixtures.scene(1, null, Fixtures.ball(3, 0), Fixtures.flag(5, 5));
        Scene stored = Fixtures.scene(2, null, Fixtures.flag(1, 1));
        assertEquals(3, metric.distance(query, stored));
        // a second instance made after compiling loads the same classes again
        assertEquals(3, REGISTRY.metric("script:" + path, PluginConfig.DEFAULT).distance(query, stored));
        Scene twoBalls = Fixtures.scene(3, null, Fixtures.ball(3, 0), Fixtures.ball(4, 0));
        assertEquals(7, assertThrows(ScriptFailure.class, () -> metric.distance(twoBalls, stored)).line());
    }

    @Test
    void failingSetUpIsReportedAtCreation() throws IOException {
        String path = write("setup.groovy", """
                if (weights.ball() == 0) {
                    throw new IllegalArgumentException('this metric needs the ball')
                }

                double distance(Scene query, Scene stored) { 0 }
                """);
        PluginConfig config = PluginConfig.DEFAULT.withObjectWeights(ObjectWeights.parse("goal=1"));
        ScriptFailure failure = assertThrows(ScriptFailure.class, () -> REGISTRY.metric("script:" + path, config));
        assertEquals(path + ":2: IllegalArgumentException: this metric needs the ball (setting up the metric)",
                failure.getMessage());
    }

    @Test
    void editedScriptIsRecompiled() throws IOException {
        String path = write("edited.groovy", "double distance(Scene query, Scene stored) { 1 }\n");
        Scene scene = Fixtures.scene(1, null);
        assertEquals(1, REGISTRY.metric("script:" + path, PluginConfig.DEFAULT).distance(scene, scene));
        write("edited.groovy", "double distance(Scene query, Scene stored) { 2 }\n");
        assertEquals(2, REGISTRY.metric("script:" + path, PluginConfig.DEFAULT).distance(scene, scene));
    }
}
