package org.scenes.plugins.script;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginException;
import org.scenes.internal.experiment.Axis;
import org.scenes.internal.experiment.Configuration;
import org.scenes.internal.experiment.Sweep;

/** Sweep scripts describe every combination of their axes, with defaults and clear errors. */
class SweepScriptTest {
    @TempDir
    Path dir;

    private String write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text).toString();
    }

    @Test
    void describesEveryCombination() throws IOException {
        String path = write("sweep.groovy", """
                title 'k and selectors'
                data 'scenes/a.json.gz', 'scenes/b.json.gz'
                metrics 'cell', 'continuous'
                weights '1/1/1/1/0/1/1/1', 'ball=1,goal=1'
                k 1..3
                k 5
                selectors 'first-valid', 'vote'
                transforms 'memory'
                protocol 'leave-one-out'
                seed 42
                table columns: 'selector', measure: 'accuracy'
                """);
        Sweep sweep = Sweeps.load(path);
        assertEquals("k and selectors", sweep.title());
        assertEquals(List.of("scenes/a.json.gz", "scenes/b.json.gz"), sweep.data());
        assertEquals(List.of(1, 2, 3, 5), sweep.ks());
        assertEquals(List.of("memory"), sweep.transforms());
        assertEquals(org.scenes.internal.validate.Folds.Protocol.LEAVE_ONE_OUT, sweep.protocol());
        assertEquals(42, sweep.seed());
        // Rows default to every other axis that varies.
        assertEquals(new Sweep.Layout(List.of(Axis.METRIC, Axis.WEIGHTS, Axis.K), Axis.SELECTOR, "accuracy"), sweep.layout());
        List<Configuration> all = sweep.configurations();
        assertEquals(2 * 2 * 4 * 2, all.size());
        assertEquals(new Configuration("cell", ObjectWeights.DEFAULT, 1, "first-valid", ActionWeights.DEFAULT), all.get(0));
        assertEquals(new Configuration("continuous", ObjectWeights.parse("ball=1,goal=1"), 5, "vote", ActionWeights.DEFAULT),
                all.get(all.size() - 1));
        assertEquals(List.of("1", "2", "3", "5"), sweep.values(Axis.K));
    }

    @Test
    void loopsAndVariablesWork() throws IOException {
        String path = write("loop.groovy", """
                data 'a.json.gz', 'b.json.gz'
                metrics 'cell'
                selectors 'first-valid'
                for (String object : ['ball', 'goal', 'flag']) {
                    weights object + '=1'
                }
                """);
        Sweep sweep = Sweeps.load(path);
        assertEquals(List.of(ObjectWeights.parse("ball=1"), ObjectWeights.parse("goal=1"), ObjectWeights.parse("flag=1")),
                sweep.weights());
        assertEquals(List.of(1), sweep.ks());
        assertEquals(List.of(), sweep.transforms());
        assertEquals(org.scenes.internal.validate.Folds.Protocol.NEXT, sweep.protocol());
        assertEquals(new Sweep.Layout(List.of(Axis.WEIGHTS), Axis.K, "accuracy"), sweep.layout());
    }

    @Test
    void explicitRowsMustCoverEveryVaryingAxis() throws IOException {
        String path = write("rows.groovy", """
                data 'a.json.gz', 'b.json.gz'
                metrics 'cell', 'continuous'
                weights 'ball=1', 'goal=1'
                selectors 'vote'
                table rows: 'metric', columns: 'k'
                """);
        PluginException e = assertThrows(PluginException.class, () -> Sweeps.load(path));
        assertEquals("the sweep " + path + " is incomplete: the table's rows are metric and its columns k, but weights "
                + "takes several values too: add it to the rows", e.getMessage());
        Files.writeString(Path.of(path), Files.readString(Path.of(path)).replace("rows: 'metric'", "rows: ['weights', 'metric']"));
        // Row axes are kept in axis order whatever order the script names them in.
        assertEquals(List.of(Axis.METRIC, Axis.WEIGHTS), Sweeps.load(path).layout().rows());
    }

    @Test
    void severalMeasuresBecomeTheColumns() throws IOException {
        String path = write("measures.groovy", """
                data 'a.json.gz', 'b.json.gz'
                metrics 'cell', 'continuous'
                selectors 'vote'
                table measures: ['accuracy', 'kick-accuracy']
                """);
        assertEquals(new Sweep.Layout(List.of(Axis.METRIC), null, List.of("accuracy", "kick-accuracy")),
                Sweeps.load(path).layout());
    }

    @Test
    void incompleteSweepSaysWhatIsMissing() throws IOException {
        String path = write("partial.groovy", "data 'a.json.gz', 'b.json.gz'\nselectors 'vote'\n");
        PluginException e = assertThrows(PluginException.class, () -> Sweeps.load(path));
        assertEquals("the sweep " + path + " is incomplete: a sweep needs at least one metric: metrics 'cell'", e.getMessage());
    }

    @Test
    void badValueIsReportedWithItsLine() throws IOException {
        String path = write("bad.groovy", """
                data 'a.json.gz', 'b.json.gz'
                metrics 'cell'
                weights '1/1/x/1/1/1/1/1'
                """);
        ScriptFailure failure = assertThrows(ScriptFailure.class, () -> Sweeps.load(path));
        assertEquals(3, failure.line());
        assertTrue(failure.getMessage().contains("object weights: 'x' is not a number"), failure.getMessage());
    }

    @Test
    void typoInAnAxisIsACompileError() throws IOException {
        String path = write("typo.groovy", "metric 'cell'\n");
        PluginException e = assertThrows(PluginException.class, () -> Sweeps.load(path));
        assertTrue(e.getMessage().contains(path + ":1:1: [Static type checking] - Cannot find matching method"), e.getMessage());
    }
}
