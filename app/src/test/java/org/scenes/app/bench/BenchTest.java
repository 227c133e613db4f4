package org.scenes.app.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.app.Progress;
import org.scenes.internal.validate.MatchConfig;

class BenchTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    /** A stand-in for the simulator's generator: a ball at a distance and direction from the seed and index. */
    private static final Bench.Generator BALLS = (seed, count, run, grid, sink) -> {
        Observer observer = new Observer("Test", Side.LEFT, 1);
        for (int i = 0; i < count; i++) {
            double distance = 1 + (seed * 7 + i) % 40;
            sink.accept(new Scene(i, observer, List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance,
                    (i % 61) - 30, grid)), List.of(Action.dash(50))));
        }
    };

    @Test
    void everyMetricThenEveryConfigurationIsARowWithItsLatencyWhenAsked() {
        Bench.Request request = new Bench.Request(List.of(), 500, 1, BALLS,
                List.of(new Bench.Metric("ball-goal", "ball-goal", PluginConfig.DEFAULT)),
                List.of(new Bench.Configured("k3.json", MatchConfig.DEFAULT.withK(3))), List.of(), 16, true, 0.02);
        Bench.Prepared prepared = Bench.prepare(request, REGISTRY, Progress.NONE);
        assertEquals(500, prepared.stored().size());
        assertEquals(16, prepared.queries().size());
        List<Bench.Row> rows = new ArrayList<>();
        Bench.measure(prepared, REGISTRY, rows::add);
        assertEquals(List.of("ball-goal", "k3.json"), rows.stream().map(Bench.Row::label).toList());
        for (Bench.Row row : rows) {
            assertTrue(row.scenesPer100ms() > 0, row.label());
            assertNotNull(row.latency());
            assertTrue(row.latency()[0] <= row.latency()[1] && row.latency()[2] <= row.latency()[3], row.label());
        }
        Bench.Request quick = new Bench.Request(List.of(), 100, 1, BALLS, List.of(), List.of(), List.of(), 4, false, 0.01);
        List<Bench.Row> none = new ArrayList<>();
        Bench.measure(Bench.prepare(quick, REGISTRY, Progress.NONE), REGISTRY, none::add);
        assertTrue(none.isEmpty());
    }

    @Test
    void withoutLatencyARowHasNoneAndTheDefaultsNameTheInstalledMetrics() {
        Bench.Request request = new Bench.Request(List.of(), 200, 1, BALLS,
                List.of(new Bench.Metric("scan", "ball-goal", PluginConfig.DEFAULT)), List.of(), List.of(), 8, false, 0.01);
        List<Bench.Row> rows = new ArrayList<>();
        Bench.measure(Bench.prepare(request, REGISTRY, Progress.NONE), REGISTRY, rows::add);
        assertNull(rows.get(0).latency());
        assertEquals(List.of("ball-goal (index)", "ball-goal (scan)", "continuous", "cell", "projection",
                "continuous (optimal)"),
                Bench.defaultMetrics(REGISTRY).stream().map(Bench.Metric::label).toList());
        assertEquals(1.5, Bench.percentile(new long[] {1000, 2000, 1500}, 0.5));
    }
}
