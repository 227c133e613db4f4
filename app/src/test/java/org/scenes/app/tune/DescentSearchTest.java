package org.scenes.app.tune;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.MetricProvider;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.SceneMetric;
import org.scenes.api.TuneDimension;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.Tuner;

/**
 * The descent's built-in search on the built-in metrics: which metrics take its side, ring and
 * previous-direction variants is what they declare for tuning, so these run with the plugins loaded
 * (core's own tests have none).
 */
class DescentSearchTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    /** An object-set-like metric that declares the side of the heading, but only 30 and no rings above 10. */
    public static final class NarrowSide implements MetricProvider {
        @Override
        public String name() {
            return "narrow-side";
        }

        @Override
        public String description() {
            return "declares side-weight 30 and row-weight 10 alone";
        }

        @Override
        public Map<String, String> options() {
            return Map.of("side-weight", "the side", "row-weight", "the rings");
        }

        @Override
        public List<TuneDimension> tuneDimensions() {
            return List.of(TuneDimension.log("side-weight", 30), TuneDimension.log("row-weight", 10));
        }

        @Override
        public SceneMetric create(PluginConfig config) {
            return (query, stored) -> 0;
        }
    }

    @Test
    void theSideAndRingVariantsFollowWhatAMetricDeclares(@TempDir Path dir) throws IOException {
        Path services = dir.resolve("META-INF/services/org.scenes.api.MetricProvider");
        Files.createDirectories(services.getParent());
        Files.writeString(services, NarrowSide.class.getName() + "\n");
        PluginRegistry registry = PluginRegistry.load(new URLClassLoader(new URL[] {dir.toUri().toURL()},
                getClass().getClassLoader()));
        List<Tuner.Dimension> search = Tuner.defaultSearch(registry);
        Tuner.Dimension side = search.stream().filter(d -> d.name().equals("side")).findFirst().orElseThrow();
        MatchConfig narrow = MatchConfig.DEFAULT.withMetric("narrow-side", Map.of("side-weight", "30", "row-weight", "10"));
        // it declares the side of the heading, so the side variants apply to it as to continuous...
        assertEquals(null, side.variants().get(0).apply(narrow).metricOptions().get("side-weight"));
        // ...and a value it does not declare stops the search before anything is scored, naming both
        IllegalStateException error = assertThrows(IllegalStateException.class,
                () -> Tuner.checkVariants(List.of(narrow), search));
        assertTrue(error.getMessage().contains("side-weight=100") && error.getMessage().contains("narrow-side")
                && error.getMessage().contains("[30.0]"), error.getMessage());
        // the built-in starts pass the same check with the built-in metrics
        Tuner.checkVariants(Tuner.defaultStarts(MatchConfig.DEFAULT), Tuner.defaultSearch(REGISTRY));
    }

    @Test
    void theBuiltInSearchCarriesSideAndPreviousDirectionAcrossMetricVariants() {
        Tuner.Dimension metric = dimension("metric");
        Tuner.Dimension memory = dimension("memory");
        Tuner.Dimension side = dimension("side");
        MatchConfig polar = metric.variants().get(3).apply(MatchConfig.DEFAULT);
        assertEquals("continuous", polar.metric());
        assertEquals("10", polar.metricOptions().get("direction-weight"));
        // memory 0.7 with the previous scene's directions at 0.3 of the current ones: 3 per degree
        MatchConfig remembered = memory.variants().get(5).apply(polar);
        assertEquals("0.7", remembered.metricOptions().get("memory"));
        assertEquals("3", remembered.metricOptions().get("memory-direction-weight"));
        MatchConfig sided = side.variants().get(2).apply(remembered);
        assertEquals("300", sided.metricOptions().get("side-weight"));
        // another polar family keeps both, and plain memory drops the previous direction weight again
        MatchConfig other = metric.variants().get(4).apply(sided);
        assertEquals("300", other.metricOptions().get("side-weight"));
        assertEquals("3", other.metricOptions().get("memory-direction-weight"));
        assertEquals(0.3, other.objectWeights().goal(), 0.0);
        assertEquals(null, memory.variants().get(4).apply(other).metricOptions().get("memory-direction-weight"));
        assertEquals(null, side.variants().get(0).apply(other).metricOptions().get("side-weight"));
        // ball-goal has neither option: the variants leave it as it is
        MatchConfig ballGoal = metric.variants().get(0).apply(sided);
        assertEquals(ballGoal, side.variants().get(3).apply(ballGoal));
        assertEquals(null, ballGoal.metricOptions().get("side-weight"));
        assertEquals(null, ballGoal.metricOptions().get("memory-direction-weight"));
        assertEquals("0.7", ballGoal.metricOptions().get("memory"));
    }

    @Test
    void theGoalsAndRingsVariantsSetTheOwnGoalShareAndTheRingWeight() {
        Tuner.Dimension goals = dimension("goals and rings");
        MatchConfig polar = Tuner.defaultStarts(MatchConfig.DEFAULT).get(1);
        MatchConfig attackedOnly = goals.variants().get(3).apply(polar);
        assertEquals("0", attackedOnly.metricOptions().get("own-goal-weight"));
        assertEquals("3000", attackedOnly.metricOptions().get("row-weight"));
        MatchConfig back = goals.variants().get(0).apply(attackedOnly);
        assertEquals(null, back.metricOptions().get("own-goal-weight"));
        assertEquals("1000", back.metricOptions().get("row-weight"));
        // a polar family without rings stays without them; ball-goal is left as it is
        MatchConfig noRings = dimension("metric").variants().get(2).apply(attackedOnly);
        assertEquals("0", noRings.metricOptions().get("own-goal-weight"), "the metric variant keeps the share");
        assertEquals(null, goals.variants().get(2).apply(noRings).metricOptions().get("row-weight"));
        MatchConfig ballGoal = Tuner.defaultStarts(MatchConfig.DEFAULT).get(0);
        assertEquals(ballGoal, goals.variants().get(3).apply(ballGoal));
    }

    private static Tuner.Dimension dimension(String name) {
        return Tuner.defaultSearch(REGISTRY).stream().filter(d -> d.name().equals(name)).findFirst().orElseThrow();
    }

}
