package org.scenes.match;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.scenes.plugin.PluginConfig;
import org.scenes.plugin.PluginException;
import org.scenes.scene.ObjectKind;
import org.scenes.scene.Relation;
import org.scenes.scene.Scene;
import org.scenes.scene.SeenObject;

/**
 * The object-by-object scene distance shared by the {@code continuous}, {@code cell} and
 * {@code projection} metrics (formulas in docs/metrics.md). Objects are split into groups that
 * only match among themselves (ball, own goal, opponent goal, flags, lines, teammates,
 * opponents, unknown players, and all players together when that class weighs); within a
 * group they are paired greedily (both sides sorted by distance to the observer, paired in
 * order) or optimally (minimum-cost assignment). An object left without partner costs a
 * penalty that grows the closer it is to the observer. The scene distance is the object-weighted
 * sum over groups, plus, with memory, the same over the remembered previous scenes and a cost
 * for differing previous actions.
 */
public final class ObjectSetMetric implements EncodedMetric<ObjectSetMetric.Encoded>, PackedMetric {
    public enum Matching { GREEDY, OPTIMAL }

    /** Where objects are placed before being compared. */
    public enum Space {
        /** x = r cos(dir), y = r sin(dir); pair cost is the straight-line distance. */
        CARTESIAN,
        /** distance and direction compared separately: wd |r1 - r2| + wa |dir1 - dir2|. */
        POLAR,
        /** grid cell (column, row); pair cost is the straight-line distance between cells. */
        CELL
    }

    /**
     * @param weights object class weights
     * @param matching how objects are paired within a group
     * @param space where objects are placed
     * @param logDistance compare ln(1 + r) instead of r (as the server's own quantisation does)
     * @param distanceWeight wd, multiplies distance differences (polar)
     * @param directionWeight wa, multiplies direction differences in degrees (polar)
     * @param rowWeight wr, multiplies differences of grid row (distance ring), added to the pair cost
     * @param penalty P, cost of an unmatched object at the observer
     * @param penaltyScale L: the penalty is P L / (L + r), half of P at r = L
     * @param projectCycles objects moved this many cycles forward (negative: back) by their changes
     * @param memoryWeight weight of the distance between remembered previous scenes
     * @param memoryActionWeight cost when the remembered previous actions differ in type
     */
    public record Settings(ObjectWeights weights, Matching matching, Space space, boolean logDistance,
                           double distanceWeight, double directionWeight, double rowWeight, double penalty, double penaltyScale,
                           double projectCycles, double memoryWeight, double memoryActionWeight) {
        public Settings {
            for (double value : new double[] {distanceWeight, directionWeight, rowWeight, penalty, memoryWeight, memoryActionWeight}) {
                if (!(value >= 0) || Double.isInfinite(value)) {
                    throw new PluginException("metric weights and penalties must be finite and not negative");
                }
            }
            if (!(penaltyScale > 0)) {
                throw new PluginException("penalty-scale must be positive, not " + penaltyScale);
            }
        }
    }

    /** Options every object-set metric accepts, with descriptions, for the providers' {@code options()}. */
    public static Map<String, String> options(boolean projection) {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("matching", "greedy (sort by distance, pair in order; default) or optimal (minimum-cost assignment)");
        options.put("log-distance", "true to compare ln(1 + distance) instead of distance (default false)");
        options.put("distance-weight", "weight of distance differences in polar space (default 1)");
        options.put("direction-weight", "weight of direction differences, per degree, in polar space (default 1)");
        options.put("row-weight", "cost per grid row (distance ring) of difference, added to the pair cost (default 0)");
        options.put("penalty", "cost of an unmatched object at the observer (default 10)");
        options.put("penalty-scale", "distance at which the unmatched penalty halves (default 10)");
        options.put("memory", "weight of the remembered previous scene (needs the memory transform; default 0)");
        options.put("memory-action", "cost when the remembered previous actions differ in type or turn direction (default 0)");
        if (projection) {
            options.put("cycles", "cycles to project objects forward by their distance/direction change (default 1; negative: back)");
        } else {
            options.put("space", "cartesian or polar (default for continuous: cartesian)");
        }
        return options;
    }

    /** Settings from a plugin config, with the defaults of the calling metric. */
    public static Settings settings(PluginConfig config, Space defaultSpace, double defaultProjection) {
        Matching matching = switch (config.option("matching", "greedy").toLowerCase(Locale.ROOT)) {
            case "greedy" -> Matching.GREEDY;
            case "optimal" -> Matching.OPTIMAL;
            default -> throw new PluginException("option matching=" + config.option("matching", "")
                    + " is unknown; use greedy or optimal");
        };
        Space space = defaultSpace;
        if (config.options().containsKey("space")) {
            space = switch (config.option("space", "").toLowerCase(Locale.ROOT)) {
                case "cartesian" -> Space.CARTESIAN;
                case "polar" -> Space.POLAR;
                default -> throw new PluginException("option space=" + config.option("space", "")
                        + " is unknown; use cartesian or polar");
            };
        }
        String log = config.option("log-distance", "false").toLowerCase(Locale.ROOT);
        if (!log.equals("true") && !log.equals("false")) {
            throw new PluginException("option log-distance=" + log + " must be true or false");
        }
        return new Settings(config.objectWeights(), matching, space, log.equals("true"),
                config.doubleOption("distance-weight", 1), config.doubleOption("direction-weight", 1),
                config.doubleOption("row-weight", 0),
                config.doubleOption("penalty", 10), config.doubleOption("penalty-scale", 10),
                config.doubleOption("cycles", defaultProjection), config.doubleOption("memory", 0),
                config.doubleOption("memory-action", 0));
    }

    // groups: ball, own goal, opponent goal, goal of unknown side, flags, lines, all players,
    // teammates, opponents, unknown players; each takes the weight of its object class
    static final int GROUPS = 10;
    private static final int[] CLASS_OF_GROUP = {0, 1, 1, 1, 2, 3, 4, 5, 6, 7};

    private static final int STRIDE = 4;

    /** A scene as packed numbers: per group (a, b, weighted row, penalty) per object, nearest first. */
    public record Encoded(double[][] groups, Encoded previous, int previousAction) {
    }

    private final Settings settings;
    private final double[] groupWeight = new double[GROUPS];
    // read on every pair: plain fields rather than record accessors and enum compares
    private final boolean polar;
    private final boolean greedy;

    public ObjectSetMetric(Settings settings) {
        this.settings = settings;
        polar = settings.space() == Space.POLAR;
        greedy = settings.matching() == Matching.GREEDY;
        double[] classWeights = settings.weights().toArray();
        for (int group = 0; group < GROUPS; group++) {
            groupWeight[group] = classWeights[CLASS_OF_GROUP[group]];
        }
    }

    public Settings settings() {
        return settings;
    }

    /**
     * True for optimal matching when the unmatched penalty changes no faster than the pair cost
     * (then a missing object acts as a point at distance penalty from all others, and the
     * minimum-cost matching distance is a metric). Greedy pairing can break the triangle inequality.
     */
    @Override
    public boolean isTrueMetric() {
        if (settings.matching() != Matching.OPTIMAL) {
            return false;
        }
        return penaltySlope() <= pairCostSlope() + 1e-12;
    }

    /** Largest rate of change of the penalty per unit of the compared radial coordinate. */
    private double penaltySlope() {
        double p = settings.penalty();
        double l = settings.penaltyScale();
        if (!settings.logDistance() || settings.space() == Space.CELL) {
            return p / l;
        }
        // penalty as a function of g = ln(1 + r): P L e^g / (L - 1 + e^g)^2, largest at e^g = max(1, L - 1)
        double u = Math.max(1, l - 1);
        return p * l * u / ((l - 1 + u) * (l - 1 + u));
    }

    /** How much the pair cost grows at least per unit of radial coordinate. */
    private double pairCostSlope() {
        return settings.space() == Space.POLAR ? settings.distanceWeight() : 1;
    }

    @Override
    public Encoded encode(Scene scene) {
        return encode(scene, true);
    }

    private Encoded encode(Scene scene, boolean withMemory) {
        if (scene == null) {
            return new Encoded(new double[GROUPS][0], null, -1);
        }
        List<List<double[]>> groups = new ArrayList<>(GROUPS);
        for (int group = 0; group < GROUPS; group++) {
            groups.add(new ArrayList<>());
        }
        for (SeenObject object : scene.objects()) {
            int group = groupOf(object);
            if (group >= 0 && groupWeight[group] > 0) {
                groups.get(group).add(place(object));
            }
            if (object.kind() == ObjectKind.PLAYER && groupWeight[6] > 0) {
                groups.get(6).add(place(object));
            }
        }
        double[][] packed = new double[GROUPS][];
        for (int group = 0; group < GROUPS; group++) {
            List<double[]> points = groups.get(group);
            points.sort(Comparator.comparingDouble((double[] point) -> point[STRIDE]));
            packed[group] = new double[points.size() * STRIDE];
            for (int i = 0; i < points.size(); i++) {
                System.arraycopy(points.get(i), 0, packed[group], i * STRIDE, STRIDE);
            }
        }
        boolean remember = withMemory && (settings.memoryWeight() > 0 || settings.memoryActionWeight() > 0);
        Encoded previous = remember && settings.memoryWeight() > 0 ? encode(scene.previous(), false) : null;
        int previousAction = remember && scene.previous() != null ? actionClass(scene.previous()) : -1;
        return new Encoded(packed, previous, previousAction);
    }

    /**
     * A scene's action as compared by memory: the primary type, with turns split by the sign of
     * the moment (left, straight, right), since the direction of a turn is what an agent repeats.
     */
    public static int actionClass(Scene scene) {
        int type = scene.actionType().ordinal();
        if (scene.actionType() != org.scenes.scene.ActionType.TURN) {
            return type * 3;
        }
        return type * 3 + 1 + (int) Math.signum(scene.primaryAction().first());
    }

    private static int groupOf(SeenObject object) {
        return switch (object.kind()) {
            case BALL -> 0;
            case GOAL -> object.relation() == Relation.OWN ? 1 : object.relation() == Relation.OPPONENT ? 2 : 3;
            case FLAG -> 4;
            case LINE -> 5;
            case PLAYER -> object.relation() == Relation.TEAMMATE ? 7 : object.relation() == Relation.OPPONENT ? 8 : 9;
        };
    }

    /** (a, b, weighted row, penalty, sort key) of one object in the configured space. */
    private double[] place(SeenObject object) {
        double r = object.distance();
        double direction = Double.isNaN(object.direction()) ? 0 : object.direction();
        if (settings.projectCycles() != 0) {
            if (!Double.isNaN(object.distanceChange()) && !Double.isNaN(r)) {
                r = Math.max(0, r + settings.projectCycles() * object.distanceChange());
            }
            if (!Double.isNaN(object.directionChange())) {
                direction += settings.projectCycles() * object.directionChange();
            }
        }
        if (Double.isNaN(r)) {
            r = 100; // not sent: as far as the field allows
        }
        double radial = settings.logDistance() ? Math.log1p(r) : r;
        double a;
        double b;
        double penaltyDistance = r;
        switch (settings.space()) {
            case CARTESIAN -> {
                double radians = Math.toRadians(direction);
                a = radial * Math.cos(radians);
                b = radial * Math.sin(radians);
            }
            case POLAR -> {
                a = settings.distanceWeight() * radial;
                b = settings.directionWeight() * direction;
            }
            default -> {
                a = object.cell().column();
                b = object.cell().row();
                penaltyDistance = object.cell().row();
            }
        }
        double l = settings.penaltyScale();
        double penalty = settings.penalty() * l / (l + penaltyDistance);
        return new double[] {a, b, settings.rowWeight() * object.cell().row(), penalty, r};
    }

    @Override
    public double distance(Encoded query, Encoded stored, double bound) {
        double total = 0;
        if (settings.memoryActionWeight() > 0 && query.previousAction() != stored.previousAction()) {
            total += settings.memoryActionWeight();
        }
        total = groupsDistance(query, stored, total, bound, 1);
        if (total > bound) {
            return total;
        }
        if (settings.memoryWeight() > 0) {
            Encoded empty = EMPTY;
            total = groupsDistance(query.previous() == null ? empty : query.previous(),
                    stored.previous() == null ? empty : stored.previous(), total, bound, settings.memoryWeight());
        }
        return total;
    }

    private static final Encoded EMPTY = new Encoded(new double[GROUPS][0], null, -1);

    private double groupsDistance(Encoded query, Encoded stored, double total, double bound, double scale) {
        for (int group = 0; group < GROUPS; group++) {
            double weight = groupWeight[group];
            if (weight == 0) {
                continue;
            }
            total += scale * weight * groupDistance(query.groups()[group], stored.groups()[group]);
            if (total > bound) {
                return total;
            }
        }
        return total;
    }

    private double pairCost(double[] x, int i, double[] y, int j) {
        double da = x[i] - y[j];
        double db = x[i + 1] - y[j + 1];
        double rows = Math.abs(x[i + 2] - y[j + 2]);
        return rows + (polar ? Math.abs(da) + Math.abs(db) : Math.sqrt(da * da + db * db));
    }

    private double groupDistance(double[] x, double[] y) {
        return groupDistance(x, 0, x.length / STRIDE, y, 0, y.length / STRIDE, 0, 1, Double.POSITIVE_INFINITY);
    }

    /**
     * Distance between n objects of x from offset xs and m objects of y from offset ys. For
     * optimal matching, when a lower bound of the assignment (the larger of the sums of row and
     * of column minima of the cost matrix) already makes {@code before + weight * cost} exceed
     * {@code bound}, that bound is returned without solving the assignment: the caller then
     * computes the same sum, above the bound, and drops the scene as the exact cost would.
     */
    private double groupDistance(double[] x, int xs, int n, double[] y, int ys, int m, double before, double weight, double bound) {
        if (n == 0 && m == 0) {
            return 0;
        }
        if (greedy || n <= 1 && m <= 1) {
            double total = 0;
            int paired = Math.min(n, m);
            for (int i = 0; i < paired; i++) {
                double cost = pairCost(x, xs + i * STRIDE, y, ys + i * STRIDE);
                if (!greedy) {
                    cost = Math.min(cost, x[xs + i * STRIDE + 3] + y[ys + i * STRIDE + 3]);
                }
                total += cost;
            }
            for (int i = paired; i < n; i++) {
                total += x[xs + i * STRIDE + 3];
            }
            for (int j = paired; j < m; j++) {
                total += y[ys + j * STRIDE + 3];
            }
            return total;
        }
        // pad the smaller side with "missing" entries that cost the other object's penalty
        int size = Math.max(n, m);
        double[] cost = new double[size * size];
        for (int i = 0; i < size; i++) {
            for (int j = 0; j < size; j++) {
                double value;
                if (i < n && j < m) {
                    value = Math.min(pairCost(x, xs + i * STRIDE, y, ys + j * STRIDE), x[xs + i * STRIDE + 3] + y[ys + j * STRIDE + 3]);
                } else if (i < n) {
                    value = x[xs + i * STRIDE + 3];
                } else if (j < m) {
                    value = y[ys + j * STRIDE + 3];
                } else {
                    value = 0;
                }
                cost[i * size + j] = value;
            }
        }
        if (bound < Double.POSITIVE_INFINITY) {
            double lower = Math.max(rowMinima(cost, size), columnMinima(cost, size));
            // shaved so rounding in the solver's own sum can never put the true cost below it
            lower *= 1 - 1e-9;
            if (before + weight * lower > bound) {
                return lower;
            }
        }
        return Assignment.minimumCost(cost, size);
    }

    /**
     * A lower bound of the optimal group distance without building the cost matrix: each object
     * of the larger side costs at least its cheapest option (a partner or going unmatched).
     */
    private double lowerBound(double[] x, int n, double[] y, int ys, int m) {
        if (n <= 1 && m <= 1) {
            return groupDistance(x, 0, n, y, ys, m, 0, 1, Double.POSITIVE_INFINITY);
        }
        double sum = 0;
        if (n >= m) {
            for (int i = 0; i < n; i++) {
                double min = x[i * STRIDE + 3];
                for (int j = 0; j < m; j++) {
                    min = Math.min(min, pairCost(x, i * STRIDE, y, ys + j * STRIDE));
                }
                sum += min;
            }
        } else {
            for (int j = 0; j < m; j++) {
                double min = y[ys + j * STRIDE + 3];
                for (int i = 0; i < n; i++) {
                    min = Math.min(min, pairCost(x, i * STRIDE, y, ys + j * STRIDE));
                }
                sum += min;
            }
        }
        return sum;
    }

    private static double rowMinima(double[] cost, int size) {
        double sum = 0;
        for (int i = 0; i < size; i++) {
            double min = Double.POSITIVE_INFINITY;
            for (int j = 0; j < size; j++) {
                min = Math.min(min, cost[i * size + j]);
            }
            sum += min;
        }
        return sum;
    }

    private static double columnMinima(double[] cost, int size) {
        double sum = 0;
        for (int j = 0; j < size; j++) {
            double min = Double.POSITIVE_INFINITY;
            for (int i = 0; i < size; i++) {
                min = Math.min(min, cost[i * size + j]);
            }
            sum += min;
        }
        return sum;
    }

    /**
     * The knowledge base as one flat array per group (objects of all scenes back to back, each
     * scene's nearest first) and per group the offset where each scene starts: no object per
     * scene or per object. Not for memory terms, which compare previous scenes too.
     */
    @Override
    public PackedScenes pack(List<Scene> scenes) {
        if (settings.memoryWeight() > 0 || settings.memoryActionWeight() > 0) {
            return null;
        }
        int n = scenes.size();
        int[][] starts = new int[GROUPS][n + 1];
        double[][][] perScene = new double[n][][];
        for (int i = 0; i < n; i++) {
            perScene[i] = encode(scenes.get(i), false).groups();
            for (int group = 0; group < GROUPS; group++) {
                starts[group][i + 1] = starts[group][i] + perScene[i][group].length;
            }
        }
        double[][] data = new double[GROUPS][];
        for (int group = 0; group < GROUPS; group++) {
            data[group] = new double[starts[group][n]];
            for (int i = 0; i < n; i++) {
                System.arraycopy(perScene[i][group], 0, data[group], starts[group][i], perScene[i][group].length);
            }
        }
        return new Packed(data, starts, n);
    }

    /** Scans like {@link #distance(Encoded, Encoded, double)}: same group order, same sums, same abandoning. */
    private final class Packed implements PackedScenes {
        private final double[][] data;
        private final int[][] starts;
        private final int size;
        private final int[] activeGroups;

        Packed(double[][] data, int[][] starts, int size) {
            this.data = data;
            this.starts = starts;
            this.size = size;
            activeGroups = java.util.stream.IntStream.range(0, GROUPS).filter(g -> groupWeight[g] != 0).toArray();
        }

        @Override
        public void scan(Scene query, TopK top) {
            double[][] q = encode(query, false).groups();
            if (greedy) {
                for (int i = 0; i < size; i++) {
                    offer(q, i, top);
                }
                return;
            }
            // optimal: scenes in order of a cheap lower bound, stopping once it exceeds the k-th best
            double[] lower = new double[size];
            Integer[] order = new Integer[size];
            for (int i = 0; i < size; i++) {
                double sum = 0;
                for (int group : activeGroups) {
                    int start = starts[group][i];
                    sum += groupWeight[group] * lowerBound(q[group], q[group].length / STRIDE, data[group], start,
                            (starts[group][i + 1] - start) / STRIDE);
                }
                lower[i] = sum * (1 - 1e-9); // shaved: the exact sums round differently
                order[i] = i;
            }
            java.util.Arrays.sort(order, (a, b) -> Double.compare(lower[a], lower[b]));
            for (int i : order) {
                if (lower[i] > top.bound()) {
                    return;
                }
                offer(q, i, top);
            }
        }

        private void offer(double[][] q, int i, TopK top) {
            double bound = top.bound();
            double total = 0;
            for (int group : activeGroups) {
                int start = starts[group][i];
                int count = (starts[group][i + 1] - start) / STRIDE;
                double weight = groupWeight[group];
                total += weight * groupDistance(q[group], 0, q[group].length / STRIDE, data[group], start, count, total, weight, bound);
                if (total > bound) {
                    return;
                }
            }
            top.offer(total, i); // NaN too, which the heap ranks farthest
        }
    }
}
