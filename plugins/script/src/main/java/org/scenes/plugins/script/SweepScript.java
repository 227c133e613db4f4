package org.scenes.plugins.script;

import groovy.lang.Script;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.internal.experiment.Axis;
import org.scenes.internal.experiment.Sweep;
import org.scenes.internal.validate.Folds;

/**
 * Base class of sweep scripts ({@code scenes experiment SWEEP.groovy}): the script's statements
 * call these methods to describe the sweep, which {@link #sweep()} then returns. Every list
 * method may be called more than once; its values add up.
 */
public abstract class SweepScript extends Script {
    private String title = "";
    private final List<String> data = new ArrayList<>();
    private final List<String> metrics = new ArrayList<>();
    private final List<ObjectWeights> weights = new ArrayList<>();
    private final List<Integer> ks = new ArrayList<>();
    private final List<String> selectors = new ArrayList<>();
    private final List<ActionWeights> actionWeights = new ArrayList<>();
    private final List<String> transforms = new ArrayList<>();
    private Folds.Protocol protocol = Folds.Protocol.NEXT;
    private long seed = 1;
    private List<Axis> rows = List.of();
    private Axis columns = Axis.K;
    private boolean columnsGiven;
    private List<String> measures = List.of("accuracy");

    /** Heading of the table and chart. */
    public void title(String text) {
        this.title = text;
    }

    /**
     * The scene files of the cross-validation, relative to the working directory, at least two:
     * each is one fold, tested against the next one (as {@code scenes validate --folds}).
     */
    public void data(String... paths) {
        data.addAll(List.of(paths));
    }

    /**
     * Which files train each fold: {@code 'next'} (the thesis' protocol, the default) or
     * {@code 'leave-one-out'} (all the other files), as {@code scenes validate --protocol}.
     */
    public void protocol(String name) {
        Folds.Protocol chosen = Folds.Protocol.fromKey(name);
        if (chosen == null) {
            throw new IllegalArgumentException("protocol must be " + Folds.Protocol.keys() + ", not '" + name + "'");
        }
        protocol = chosen;
    }

    /** Scene transforms applied in every configuration, e.g. {@code transforms 'memory'}. */
    public void transforms(String... names) {
        transforms.addAll(List.of(names));
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

    /** Seed of every random choice, the same for each configuration (default 1). */
    public void seed(long value) {
        this.seed = value;
    }

    /**
     * How the results table is pivoted. Either one measure over the values of an axis,
     * {@code table columns: 'k', measure: 'accuracy'}, or several measures side by side,
     * {@code table measures: ['accuracy', 'kick-accuracy']}. Rows are every other axis that takes
     * several values, or {@code rows: 'metric'} / {@code rows: ['metric', 'weights']}. Axes:
     * metric, weights, k, selector, action-weights. Default: columns k, measure accuracy.
     */
    public void table(Map<String, ?> spec) {
        for (Map.Entry<String, ?> entry : spec.entrySet()) {
            Object value = entry.getValue();
            switch (entry.getKey()) {
                case "rows" -> {
                    List<Axis> axes = new ArrayList<>();
                    for (Object axis : value instanceof List<?> list ? list : List.of(value)) {
                        axes.add(Axis.fromKey(String.valueOf(axis)));
                    }
                    rows = axes;
                }
                case "columns" -> {
                    columns = Axis.fromKey(String.valueOf(value));
                    columnsGiven = true;
                }
                case "measure", "measures" -> {
                    List<String> names = new ArrayList<>();
                    for (Object name : value instanceof List<?> list ? list : List.of(value)) {
                        names.add(String.valueOf(name));
                    }
                    measures = names;
                }
                default -> throw new IllegalArgumentException("table takes rows, columns and measure(s), not '"
                        + entry.getKey() + "'");
            }
        }
        if (!columnsGiven && measures.size() > 1) {
            columns = null;
        }
    }

    /** The sweep the script described, with defaults for what it left out. */
    public Sweep sweep() {
        // Every axis but the columns as rows is always a valid layout; the real one is chosen from its values.
        List<Axis> allRows = new ArrayList<>(List.of(Axis.values()));
        if (columns != null) {
            allRows.remove(columns);
        }
        Sweep sweep = new Sweep(title, data, metrics, weights.isEmpty() ? List.of(ObjectWeights.DEFAULT) : weights,
                ks.isEmpty() ? List.of(1) : ks, selectors,
                actionWeights.isEmpty() ? List.of(ActionWeights.DEFAULT) : actionWeights, protocol, transforms, seed,
                new Sweep.Layout(allRows, columns, measures));
        return sweep.withLayout(Sweep.Layout.of(rows, columns, measures, sweep));
    }
}
