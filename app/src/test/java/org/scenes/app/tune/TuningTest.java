package org.scenes.app.tune;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.app.TestFiles;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfigFile;
import org.scenes.internal.validate.RandomSearch;
import org.scenes.internal.validate.Tuner;

class TuningTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    @TempDir
    Path dir;

    private Tuning.Request request() throws Exception {
        List<Path> train = List.of(TestFiles.krislet(dir.resolve("a.json"), 1, 80), TestFiles.krislet(dir.resolve("b.json"), 2, 70),
                TestFiles.krislet(dir.resolve("c.json"), 3, 60));
        return new Tuning.Request(train, Folds.Protocol.LEAVE_ONE_OUT, Tuner.Objective.MEAN, 1);
    }

    @Test
    void theDescentScoresEveryConfigurationItTriesAndNamesItsBlock() throws Exception {
        List<String> lines = new ArrayList<>();
        Tuning.Outcome outcome = Tuning.descent(request(), 1, REGISTRY, lines::add);
        assertEquals(outcome.tried().size(), lines.size());
        assertEquals(outcome.configurations(), outcome.tried().size());
        Map<String, Object> block = outcome.crossValidation();
        assertEquals(List.of("score", "protocol", "objective", "scoreFormula", "figures", "configurationsTried", "trainFiles"),
                List.copyOf(block.keySet()));
        assertEquals("leave-one-out", block.get("protocol"));
        assertEquals(outcome.score(), block.get("score"));
        double best = outcome.tried().stream().mapToDouble(RandomSearch.Tried::score).max().orElseThrow();
        assertEquals(best, outcome.score(), 1e-9);
        Path file = dir.resolve("tuned.json");
        MatchConfigFile.write(file, outcome.config(), Map.of("crossValidation", block));
        assertEquals(outcome.config(), MatchConfigFile.read(file));
    }

    @Test
    void theRandomSearchCountsDistinctConfigurationsAndIsSeeded() throws Exception {
        Tuning.Request request = request();
        Tuning.Outcome first = Tuning.random(request, List.of(), 8, Long.MAX_VALUE, REGISTRY, null);
        Tuning.Outcome again = Tuning.random(request, List.of(), 8, Long.MAX_VALUE, REGISTRY, null);
        assertEquals(first.config(), again.config());
        assertEquals(first.tried().stream().map(RandomSearch.Tried::config).distinct().count(),
                first.crossValidation().get("configurationsTried"));
        assertEquals(first.tried().size(), first.crossValidation().get("scores"));
        assertTrue(first.configurations() <= 8 && first.configurations() > 0);
        assertEquals(List.of("a.json", "b.json", "c.json"), ((List<?>) first.crossValidation().get("trainFiles")).stream()
                .map(name -> Path.of(name.toString()).getFileName().toString()).toList());
    }

    @Test
    void theRandomSearchDrawsOnlyTheMetricsAskedFor() throws Exception {
        Tuning.Outcome outcome = Tuning.random(request(), List.of("cell", "ball-goal"), 30, Long.MAX_VALUE, REGISTRY, null);
        List<String> drawn = outcome.tried().stream().map(tried -> tried.config().metric()).distinct().sorted().toList();
        assertEquals(List.of("ball-goal", "cell"), drawn);
        assertEquals(List.of("cell", "ball-goal"), outcome.crossValidation().get("metrics"));
        PluginException unknown = assertThrows(PluginException.class,
                () -> Tuning.random(request(), List.of("nearest"), 4, Long.MAX_VALUE, REGISTRY, null));
        assertTrue(unknown.getMessage().contains("Available metrics: "), unknown.getMessage());
        PluginException nothing = assertThrows(PluginException.class,
                () -> Tuning.random(request(), List.of("random"), 4, Long.MAX_VALUE, REGISTRY, null));
        assertTrue(nothing.getMessage().contains("'random' declares nothing to search; searchable: ball-goal"),
                nothing.getMessage());
    }
}
