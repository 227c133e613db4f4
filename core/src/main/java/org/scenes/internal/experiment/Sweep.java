package org.scenes.internal.experiment;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.internal.validate.Folds;

/**
 * A parameter sweep: every combination of metrics x object weights x k x selectors x action
 * weights, each validated on the same scene files with the same folds and seed, so that any
 * one configuration gives the same numbers alone as inside the sweep. The layout says how the
 * results table is pivoted for reading and drawing.
 *
 * @param title heading of the table and the chart
 * @param data the scene files of the cross-validation, one fold each: each file is tested
 *             in turn, as {@code scenes validate --folds} does
 * @param protocol which files train each fold: the next one (the thesis' protocol) or all others
 * @param transforms scene transforms applied in every configuration ({@code memory}), in order
 * @param seed seed of every random choice, the same for each configuration
 * @param layout which axes are rows and columns of the table, and which measures fill it
 */
public record Sweep(String title, List<String> data, List<String> metrics, List<ObjectWeights> weights, List<Integer> ks,
                    List<String> selectors, List<ActionWeights> actionWeights, Folds.Protocol protocol,
                    List<String> transforms, long seed, Layout layout) {

    /**
     * How the results are pivoted into the table (and chart): rows are combinations of axis
     * values; columns are either the values of one more axis, showing one measure
     * ({@code columns k, measure accuracy}), or several measures ({@code columns null}).
     *
     * @param rows the axes whose value combinations are the table's rows, kept in axis order;
     *             every axis that takes several values and is not the columns must be one of them
     * @param columns the axis whose values are the columns, or null for one column per measure
     * @param measures the measures shown: exactly one when the columns are an axis
     */
    public record Layout(List<Axis> rows, Axis columns, List<String> measures) {
        public Layout {
            rows = Arrays.stream(Axis.values()).filter(rows::contains).toList();
            measures = List.copyOf(measures);
            if (rows.isEmpty()) {
                throw new IllegalArgumentException("the table needs at least one row axis");
            }
            if (columns != null && rows.contains(columns)) {
                throw new IllegalArgumentException("the table's rows and columns must be different axes, not both "
                        + columns.key());
            }
            if (measures.isEmpty()) {
                throw new IllegalArgumentException("the table needs a measure: measure: 'accuracy'");
            }
            if (columns != null && measures.size() != 1) {
                throw new IllegalArgumentException("a table whose columns are " + columns.key()
                        + " shows one measure, not " + measures.size() + "; leave out columns to show several");
            }
        }

        public Layout(List<Axis> rows, Axis columns, String measure) {
            this(rows, columns, List.of(measure));
        }

        public boolean columnsAreMeasures() {
            return columns == null;
        }

        /** "k", or "measure" when the columns are measures. */
        public String columnsKey() {
            return columns == null ? "measure" : columns.key();
        }

        /**
         * Rows unless given: every axis besides the columns that takes several values, or the
         * metric when none does.
         */
        public static Layout of(List<Axis> rows, Axis columns, List<String> measures, Sweep sweep) {
            if (!rows.isEmpty()) {
                return new Layout(rows, columns, measures);
            }
            List<Axis> varying = new ArrayList<>();
            for (Axis axis : Axis.values()) {
                if (axis != columns && sweep.values(axis).size() > 1) {
                    varying.add(axis);
                }
            }
            return new Layout(varying.isEmpty() ? List.of(columns == Axis.METRIC ? Axis.K : Axis.METRIC) : varying,
                    columns, measures);
        }
    }

    public Sweep {
        data = List.copyOf(data);
        metrics = List.copyOf(metrics);
        weights = List.copyOf(weights);
        ks = List.copyOf(ks);
        selectors = List.copyOf(selectors);
        actionWeights = List.copyOf(actionWeights);
        transforms = List.copyOf(transforms);
        protocol = protocol == null ? Folds.Protocol.NEXT : protocol;
        require(data.size() >= 2, "a sweep needs at least two scene files, one per fold: data 'a.json.gz', 'b.json.gz'");
        require(!metrics.isEmpty(), "a sweep needs at least one metric: metrics 'cell'");
        require(!weights.isEmpty(), "a sweep needs at least one object weight vector");
        require(!ks.isEmpty(), "a sweep needs at least one k");
        require(!selectors.isEmpty(), "a sweep needs at least one selector: selectors 'first-valid'");
        require(!actionWeights.isEmpty(), "a sweep needs at least one action weight vector");
        for (int k : ks) {
            require(k >= 1, "k must be at least 1, not " + k);
        }
        for (Axis axis : Axis.values()) {
            // The table has one cell per row and column value: any other axis must be fixed.
            require(layout.rows().contains(axis) || axis == layout.columns() || values(axis, metrics, weights, ks,
                    selectors, actionWeights).size() == 1, "the table's rows are " + keys(layout.rows()) + " and its columns "
                    + layout.columnsKey() + ", but " + axis.key() + " takes several values too: add it to the rows");
        }
    }

    static String keys(List<Axis> axes) {
        return String.join(" x ", axes.stream().map(Axis::key).toList());
    }

    /** The same sweep with another layout. */
    public Sweep withLayout(Layout newLayout) {
        return new Sweep(title, data, metrics, weights, ks, selectors, actionWeights, protocol, transforms, seed, newLayout);
    }

    private static void require(boolean condition, String message) {
        if (!condition) {
            throw new IllegalArgumentException(message);
        }
    }

    /** Every combination, in a fixed order: metric slowest, action weights fastest. */
    public List<Configuration> configurations() {
        List<Configuration> all = new ArrayList<>();
        for (String metric : metrics) {
            for (ObjectWeights weight : weights) {
                for (int k : ks) {
                    for (String selector : selectors) {
                        for (ActionWeights action : actionWeights) {
                            all.add(new Configuration(metric, weight, k, selector, action));
                        }
                    }
                }
            }
        }
        return all;
    }

    /** The values an axis takes, in sweep order. */
    public List<String> values(Axis axis) {
        return values(axis, metrics, weights, ks, selectors, actionWeights);
    }

    private static List<String> values(Axis axis, List<String> metrics, List<ObjectWeights> weights, List<Integer> ks,
                                       List<String> selectors, List<ActionWeights> actionWeights) {
        return switch (axis) {
            case METRIC -> metrics;
            case WEIGHTS -> weights.stream().map(ObjectWeights::format).toList();
            case K -> ks.stream().map(String::valueOf).toList();
            case SELECTOR -> selectors;
            case ACTION_WEIGHTS -> actionWeights.stream().map(ActionWeights::format).toList();
        };
    }
}
