package org.scenes.plugins.ballgoal;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.EncodedMetric;
import org.scenes.api.MetricProvider;
import org.scenes.api.ObjectKind;
import org.scenes.api.ObjectSetMetrics;
import org.scenes.api.PackedMetric;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.api.TuneDimension;

/**
 * {@code ball-goal}: only the ball and the opponent goal count, each compared by its cell
 * (rows weigh more than columns) and its direction; an object seen in one scene only costs a
 * fixed amount. The thesis' best metric for Krislet, which decides on these two objects alone.
 */
public final class BallGoalMetricProvider implements MetricProvider {
    @Override
    public String name() {
        return "ball-goal";
    }

    @Override
    public String description() {
        return "ball and opponent goal only: cells (distance row weighted more) and directions";
    }

    @Override
    public Map<String, String> options() {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("row-weight", "cost per row (distance ring) of difference (default 3)");
        options.put("column-weight", "cost per column of difference (default 1)");
        options.put("angle-weight", "cost per 10 degrees of direction difference (default 0.5)");
        options.put("missing", "cost of a ball or goal seen in one scene only (default 10)");
        options.put("memory", "weight of the remembered previous scene's ball and goal (needs the memory transform; default 0)");
        options.put("memory-action", "cost when the remembered previous actions differ in type or turn direction (default 0)");
        options.put("remembered", "cost added when the ball or goal is remembered (recall transform) in one scene and seen in the other (default 0: compared alike)");
        options.put("index", "true: search an exact index of the distinct ball and goal keys; false: scan every scene (default true)");
        return options;
    }

    /** The direction, ring and column costs, in the order the search draws them. */
    @Override
    public List<TuneDimension> tuneDimensions() {
        return List.of(TuneDimension.log("angle-weight", 0.5, 2, 5, 10),
                TuneDimension.log("row-weight", 1, 3, 10, 30),
                TuneDimension.log("column-weight", 0.5, 1, 2));
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        double row = config.doubleOption("row-weight", 3);
        double column = config.doubleOption("column-weight", 1);
        double angle = config.doubleOption("angle-weight", 0.5);
        double missing = config.doubleOption("missing", 10);
        double memory = config.doubleOption("memory", 0);
        double memoryAction = config.doubleOption("memory-action", 0);
        double remembered = config.doubleOption("remembered", 0);
        for (double value : new double[] {row, column, angle, missing, memory, memoryAction, remembered}) {
            if (!(value >= 0) || Double.isInfinite(value)) {
                throw new PluginException("ball-goal weights must be finite and not negative");
            }
        }
        String index = config.option("index", "true");
        if (!index.equals("true") && !index.equals("false")) {
            throw new PluginException("ball-goal option index must be true or false, not " + index);
        }
        return new BallGoalMetric(row, column, angle / 10, missing,
                config.objectWeights().ball(), config.objectWeights().goal(), memory, memoryAction, index.equals("true"))
                .withRemembered(remembered);
    }

    /**
     * Per object, {@code min(2M, rw |row1 - row2| + cw |col1 - col2| + aw |dir1 - dir2|)} when
     * both scenes hold it, {@code M} when one does, 0 when neither; weighted by the ball and goal
     * object weights. Each term is a metric (a missing object is a point at M from all others), so the sum is too.
     */
    static final class BallGoalMetric implements EncodedMetric<double[]>, PackedMetric {
        private final double rowWeight;
        private final double columnWeight;
        private final double anglePerDegree;
        private final double missing;
        private final double ballWeight;
        private final double goalWeight;
        private final double memory;
        private final double memoryAction;
        private final boolean indexed;
        /** cost of comparing a remembered object with a seen one; remembered objects are marked only when above 0 */
        private double remembered;

        BallGoalMetric(double rowWeight, double columnWeight, double anglePerDegree, double missing,
                       double ballWeight, double goalWeight, double memory, double memoryAction, boolean indexed) {
            this.indexed = indexed;
            this.memory = memory;
            this.memoryAction = memoryAction;
            this.rowWeight = rowWeight;
            this.columnWeight = columnWeight;
            this.anglePerDegree = anglePerDegree;
            this.missing = missing;
            this.ballWeight = ballWeight;
            this.goalWeight = goalWeight;
        }

        BallGoalMetric withRemembered(double cost) {
            remembered = cost;
            return this;
        }

        /** Packed columns of the current scene's ball and goal, indexed unless disabled; none with memory terms. */
        @Override
        public PackedScenes pack(List<Scene> scenes) {
            return memory > 0 || memoryAction > 0 || remembered > 0 ? null : PackedBallGoal.pack(this, scenes, indexed);
        }

        double rowWeight() {
            return rowWeight;
        }

        double columnWeight() {
            return columnWeight;
        }

        double anglePerDegree() {
            return anglePerDegree;
        }

        double missing() {
            return missing;
        }

        double ballWeight() {
            return ballWeight;
        }

        double goalWeight() {
            return goalWeight;
        }

        @Override
        public boolean isTrueMetric() {
            return true;
        }

        /**
         * [present (1 seen, 2 remembered when that costs), column, row, direction] for the ball, then for the opponent goal; then the
         * same for the remembered previous scene, and the previous action's class (-1 for none).
         */
        @Override
        public double[] encode(Scene scene) {
            double[] features = new double[17];
            place(scene, features, 0);
            Scene previous = scene.previous();
            if (previous != null) {
                place(previous, features, 8);
            }
            features[16] = previous == null ? -1 : ObjectSetMetrics.actionClass(previous);
            return features;
        }

        private void place(Scene scene, double[] features, int start) {
            for (SeenObject object : scene.objects()) {
                int offset;
                if (object.kind() == ObjectKind.BALL) {
                    offset = start;
                } else if (object.kind() == ObjectKind.GOAL && object.relation() == Relation.OPPONENT) {
                    offset = start + 4;
                } else {
                    continue;
                }
                if (features[offset] == 0) { // the first one the server listed, should it list two
                    features[offset] = remembered > 0 && object.remembered() ? 2 : 1;
                    features[offset + 1] = object.cell().column();
                    features[offset + 2] = object.cell().row();
                    features[offset + 3] = Double.isNaN(object.direction()) ? 0 : object.direction();
                }
            }
        }

        @Override
        public double distance(double[] query, double[] stored, double bound) {
            double distance = ballWeight * objectDistance(query, stored, 0) + goalWeight * objectDistance(query, stored, 4);
            if (memory > 0) {
                distance += memory * (ballWeight * objectDistance(query, stored, 8) + goalWeight * objectDistance(query, stored, 12));
            }
            if (memoryAction > 0 && query[16] != stored[16]) {
                distance += memoryAction;
            }
            return distance;
        }

        private double objectDistance(double[] x, double[] y, int offset) {
            boolean inX = x[offset] != 0;
            boolean inY = y[offset] != 0;
            if (inX != inY) {
                return missing;
            }
            if (!inX) {
                return 0;
            }
            double cost = columnWeight * Math.abs(x[offset + 1] - y[offset + 1])
                    + rowWeight * Math.abs(x[offset + 2] - y[offset + 2])
                    + anglePerDegree * Math.abs(x[offset + 3] - y[offset + 3]);
            return Math.min(cost, 2 * missing) + (x[offset] != y[offset] ? remembered : 0);
        }
    }
}
