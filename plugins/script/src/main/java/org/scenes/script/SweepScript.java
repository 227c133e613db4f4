package org.scenes.script;

import groovy.lang.Script;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.scenes.experiment.Axis;
import org.scenes.experiment.Sweep;
import org.scenes.match.ActionWeights;
import org.scenes.match.ObjectWeights;

/**
 * Base class of sweep scripts ({@code scenes experiment SWEEP.groovy}): the script's statements
 * call these methods to describe the sweep, which {@link #sweep()} then returns. Every list
 * method may be called more than once; its values add up.
 */
public abstract class SweepScript extends Script {
    private static final Set<String> TABLE_KEYS = Set.of("rows", "columns", "measure");

    private String title = "";
    private final List<String> data = new ArrayList<>();
    private final List<String> metrics = new ArrayList<>();
    private final List<ObjectWeights> weights = new ArrayList<>();
    private final List<Integer> ks = new ArrayList<>();
    private final List<String> selectors = new ArrayList<>();
    private final List<ActionWeights> actionWeights = new ArrayList<>();
    private int folds = 10;
    private long seed = 1;
    private Sweep.Layout layout = new Sweep.Layout(Axis.METRIC, Axis.K, "accuracy");

    /** Heading of the table and chart. */
    public void title(String text) {
        this.title = text;
    }

    /** Scene files or directories of scene files, relative to the working directory. */
    public void data(String... paths) {
        data.addAll(List.of(paths));
    }

    /** Metric specs, as on the command line: {@code 'cell'}, {@code 'script:my.groovy'}. */
    public void metrics(String... specs) {
        metrics.addAll(List.of(specs));
    }

    /** Object weight vectors: {@code '1/0/1/1/0/1/1/1'} or {@code 'ball=1,goal=1'}. */
    public void weights(String... vectors) {
        for (String vector : vectors) {
            weights.add(ObjectWeights.parse(vector));
        }
    }

    /** Numbers of neighbours: {@code k 1, 3, 5} or {@code k 1..10}. */
    public void k(int... values) {
        for (int value : values) {
            ks.add(value);
        }
    }

    public void k(List<Integer> values) {
        ks.addAll(values);
    }

    /** Selector specs: {@code 'first-valid'}, {@code 'vote'}, {@code 'script:vote.groovy'}. */
    public void selectors(String... specs) {
        selectors.addAll(List.of(specs));
    }

    /** Action weight vectors: {@code '1/1/2/1/1/1/1'} or {@code 'kick=2'}. */
    public void actionWeights(String... vectors) {
        for (String vector : vectors) {
            actionWeights.add(ActionWeights.parse(vector));
        }
    }

    /** Number of cross-validation folds (default 10). */
    public void folds(int count) {
        this.folds = count;
    }

    /** Seed of every random choice, the same for each configuration (default 1). */
    public void seed(long value) {
        this.seed = value;
    }

    /**
     * How the results table is pivoted: {@code table rows: 'metric', columns: 'k', measure: 'accuracy'}.
     * Axes: metric, weights, k, selector, action-weights.
     */
    public void table(Map<String, String> spec) {
        for (String key : spec.keySet()) {
            if (!TABLE_KEYS.contains(key)) {
                throw new IllegalArgumentException("table takes rows, columns and measure, not '" + key + "'");
            }
        }
        Axis rows = spec.containsKey("rows") ? Axis.fromKey(spec.get("rows")) : layout.rows();
        Axis columns = spec.containsKey("columns") ? Axis.fromKey(spec.get("columns")) : layout.columns();
        String measure = spec.getOrDefault("measure", layout.measure());
        layout = new Sweep.Layout(rows, columns, measure);
    }

    /** The sweep the script described, with defaults for what it left out. */
    public Sweep sweep() {
        return new Sweep(title, data, metrics, weights.isEmpty() ? List.of(ObjectWeights.DEFAULT) : weights,
                ks.isEmpty() ? List.of(1) : ks, selectors,
                actionWeights.isEmpty() ? List.of(ActionWeights.DEFAULT) : actionWeights, folds, seed, layout);
    }
}
