package org.scenes.app.validate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.PluginRegistry;
import org.scenes.app.Progress;
import org.scenes.app.TestFiles;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileException;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.Validator;

class ValidationTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    @TempDir
    Path dir;

    /** Counts what a service reports. */
    private static final class Counted implements Progress {
        final AtomicLong steps = new AtomicLong();
        long total = -1;
        int ends;

        @Override
        public void begin(String task, long total) {
            this.total = total;
        }

        @Override
        public void step() {
            steps.incrementAndGet();
        }

        @Override
        public void end() {
            ends++;
        }
    }

    private Path file(String name, long seed, int count) throws Exception {
        return TestFiles.krislet(dir.resolve(name), seed, count);
    }

    @Test
    void aSplitRunIsTheValidatorsReportWithEveryQueryNamed() throws Exception {
        Path train = file("train.json", 1, 300);
        Path test = file("test.json", 2, 120);
        MatchConfig config = MatchConfig.DEFAULT;
        Counted progress = new Counted();
        List<Validation.Outcome> outcomes = Validation.run(new Validation.Request(List.of(train), List.of(test), false,
                false, Folds.Protocol.NEXT, List.of(config, config.withK(3)), List.of("one", "three"), true), REGISTRY, progress);

        assertEquals(2, outcomes.size());
        assertEquals("one", outcomes.get(0).label());
        assertEquals(240, progress.total);
        assertEquals(240, progress.steps.get());
        assertEquals(1, progress.ends);
        Validation.Outcome first = outcomes.get(0);
        assertNull(first.folds());
        assertEquals(120, first.queries().size());
        assertEquals(new Validation.Query("test.json", 7), first.queries().get(7));
        List<SceneFile> files = Validation.readSameGrid(List.of(train, test));
        KnowledgeBase knowledge = KnowledgeBase.fromFiles(files.subList(0, 1), config.transformFactory(REGISTRY));
        double direct = Validator.run(knowledge, files.get(1).scenes(), config, REGISTRY, false, null).accuracy();
        assertEquals(direct, first.accuracy());
        assertTrue(first.accuracy() > 0.5, "ball-goal learns a Krislet: " + first.accuracy());

        Path predictions = dir.resolve("predictions.csv");
        Validation.writePredictions(predictions, outcomes);
        List<String> lines = Files.readAllLines(predictions);
        assertEquals("configuration,file,cycle,recorded,predicted,type_right,direction_right,neighbour_file,"
                + "neighbour_cycle,neighbour_distance", lines.get(0));
        assertEquals(1 + 240, lines.size());
        assertTrue(lines.get(8).startsWith("one,test.json,7,"), lines.get(8));
    }

    @Test
    void eachPredictionNamesTheStoredSceneItCameFrom() throws Exception {
        // tested on two of its own training files with continuous distances and directions: each
        // query's nearest stored scene sees what it sees, at distance 0
        Path first = file("first.json", 6, 150);
        Path second = file("second.json", 7, 150);
        MatchConfig continuous = MatchConfig.DEFAULT.withMetric("continuous", java.util.Map.of());
        List<Validation.Outcome> outcomes = Validation.run(new Validation.Request(List.of(first, second), List.of(), true,
                false, Folds.Protocol.NEXT, List.of(continuous), List.of(), true), REGISTRY, new Counted());
        Validation.Outcome outcome = outcomes.get(0);
        List<SceneFile> files = Validation.readSameGrid(List.of(first, second));
        java.util.Map<String, SceneFile> byName = java.util.Map.of(first.toString(), files.get(0), "first.json", files.get(0),
                second.toString(), files.get(1), "second.json", files.get(1));
        assertEquals(300, outcome.sources().size());
        int own = 0;
        for (int i = 0; i < outcome.queries().size(); i++) {
            Validation.Query query = outcome.queries().get(i);
            Validation.Source source = outcome.sources().get(i);
            assertEquals(0, source.distance(), "query " + query);
            if (Path.of(source.file()).getFileName().toString().equals(query.file()) && source.cycle() == query.cycle()) {
                own++;
            }
            // the named scene is there and sees what the query sees (an earlier equal scene wins a tie)
            org.scenes.api.Scene named = byName.get(source.file()).scenes().stream()
                    .filter(scene -> scene.cycle() == source.cycle()).findFirst().orElseThrow();
            org.scenes.api.Scene asked = byName.get(query.file()).scenes().stream()
                    .filter(scene -> scene.cycle() == query.cycle()).findFirst().orElseThrow();
            assertEquals(asked.objects(), named.objects(), "query " + query + " against " + source);
        }
        assertTrue(own > 200, own + " of 300 found themselves");
        assertTrue(outcome.sources().stream().anyMatch(source -> source.file().equals(second.toString())));
    }

    @Test
    void crossValidationReportsFoldsAndEveryQuery() throws Exception {
        List<Path> folds = List.of(file("a.json", 3, 100), file("b.json", 4, 80), file("c.json", 5, 60));
        Counted progress = new Counted();
        List<Validation.Outcome> outcomes = Validation.run(new Validation.Request(folds, List.of(), false, true,
                Folds.Protocol.LEAVE_ONE_OUT, List.of(MatchConfig.DEFAULT), List.of(), false), REGISTRY, progress);

        Validation.Outcome outcome = outcomes.get(0);
        assertNotNull(outcome.folds());
        assertTrue(outcome.queries().isEmpty());
        assertEquals(MatchConfig.DEFAULT.describe(), outcome.label());
        assertEquals(240, progress.total);
        assertEquals(240, progress.steps.get());
    }

    @Test
    void aFileWithoutScenesIsNamedAndTheProgressEnds() throws Exception {
        Path train = file("train.json", 1, 50);
        Path empty = file("empty.json", 1, 0);
        SceneFileException error = assertThrows(SceneFileException.class, () -> Validation.run(new Validation.Request(
                List.of(train), List.of(empty), false, false, Folds.Protocol.NEXT, List.of(MatchConfig.DEFAULT), List.of(),
                true), REGISTRY, Progress.NONE));
        assertTrue(error.getMessage().contains("empty.json") && error.getMessage().contains("holds no scenes"),
                error.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Validation.Request(List.of(train), List.of(), true, false,
                Folds.Protocol.NEXT, List.of(MatchConfig.DEFAULT), List.of("a", "b"), true));
    }
}
