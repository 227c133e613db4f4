package org.scenes.internal.match;

import java.util.List;
import java.util.Map;
import org.scenes.api.ActionType;
import org.scenes.api.EncodedMetric;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PackedMetric;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.Scene;

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
     * @param memoryDepth how many previous actions that cost compares (1 to {@link Scene#MAX_MEMORY})
     * @param memoryDecay the i-th action back costs {@code memoryActionWeight · memoryDecay^(i-1)}
     * @param nearestPlayers compare only the nearest player of each player class (all players,
     *        teammates, opponents, unknown), so every group holds at most one object
     * @param memoryDirectionWeight direction weight of the remembered previous scene (polar)
     * @param sideWeight ws, added to the pair cost when the objects lie on different sides of the
     *        observer's heading: left, straight ahead, right
     * @param aheadWidth width in degrees of "straight ahead" (|direction| below half of it)
     * @param ownGoalShare the own goal's weight as a share of the goal class weight (the opponent's
     *        goal and goals of unknown side keep the whole of it)
     * @param memoryRowWeight row weight of the remembered previous scene
     */
    public record Settings(ObjectWeights weights, Matching matching, Space space, boolean logDistance,
                           double distanceWeight, double directionWeight, double rowWeight, double penalty, double penaltyScale,
                           double projectCycles, double memoryWeight, double memoryActionWeight, int memoryDepth,
                           double memoryDecay, boolean nearestPlayers, double memoryDirectionWeight,
                           double sideWeight, double aheadWidth, double ownGoalShare, double memoryRowWeight) {
        public Settings {
            if (memoryDepth < 1 || memoryDepth > Scene.MAX_MEMORY) {
                throw new PluginException("memory-depth must be a whole number from 1 to " + Scene.MAX_MEMORY + ", not " + memoryDepth);
            }
            if (!(memoryDecay >= 0) || Double.isInfinite(memoryDecay)) {
                throw new PluginException("memory-decay must be finite and not negative, not " + memoryDecay);
            }
            for (double value : new double[] {distanceWeight, directionWeight, rowWeight, penalty, memoryWeight, memoryActionWeight,
                    memoryDirectionWeight, sideWeight, aheadWidth, ownGoalShare, memoryRowWeight}) {
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
        return ObjectSetOptions.describe(projection);
    }

    /** The metric a plugin config asks for, with the defaults of the calling metric (and its {@code index} option). */
    public static ObjectSetMetric create(PluginConfig config, Space defaultSpace, double defaultProjection) {
        boolean indexed = ObjectSetOptions.indexed(config);
        return new ObjectSetMetric(settings(config, defaultSpace, defaultProjection), indexed);
    }

    /** Settings from a plugin config, with the defaults of the calling metric. */
    public static Settings settings(PluginConfig config, Space defaultSpace, double defaultProjection) {
        return ObjectSetOptions.settings(config, defaultSpace, defaultProjection);
    }

    // groups: ball, own goal, opponent goal, goal of unknown side, flags, lines, all players,
    // teammates, opponents, unknown players; each takes the weight of its object class
    static final int GROUPS = 10;
    private static final int[] CLASS_OF_GROUP = {0, 1, 1, 1, 2, 3, 4, 5, 6, 7};
    private static final int OWN_GOAL = 1;

    /**
     * A scene as packed numbers: per group, per object nearest first, {@link #stride()} 32-bit
     * floats: a and b; the penalty unless it follows from them (see {@link #penalty}); then the
     * additive coordinates, whose absolute differences add to the pair cost: with a row weight
     * the weighted row, with a side weight two side coordinates (left (0, 0), ahead (ws/2, ws/2),
     * right (ws, 0): any two sides are ws apart).
     */
    public record Encoded(float[][] groups, Encoded previous, int[] actions) {
    }

    private final Settings settings;
    private final double[] groupWeight = new double[GROUPS];
    // read on every pair: plain fields rather than record accessors and enum compares
    private final boolean polar;
    private final boolean greedy;
    private final int stride;
    /** Where the penalty is within an object's floats; -1 when not stored. */
    private final int penaltyAt;
    /** Where the additive coordinates (weighted row, sides) start: up to the stride. */
    private final int additiveAt;
    private final boolean cell;
    private final double penaltyTimesScale;
    /** Whether {@link #pack} may build the {@link LowDimensionalIndex}. */
    private final boolean indexed;
    private final ObjectSetEncoder encoder;
    // scratch of the Encoded path; a metric instance serves one thread at a time
    private Assignment.Workspace workspace;

    public ObjectSetMetric(Settings settings) {
        this(settings, true);
    }

    /** @param indexed whether low-dimensional configurations search an exact index (else every scene is scanned) */
    public ObjectSetMetric(Settings settings, boolean indexed) {
        this.settings = settings;
        this.indexed = indexed;
        polar = settings.space() == Space.POLAR;
        greedy = settings.matching() == Matching.GREEDY;
        boolean rows = settings.rowWeight() > 0 || settings.memoryRowWeight() > 0;
        cell = settings.space() == Space.CELL;
        // the penalty is a function of the stored position when that holds the distance itself
        boolean derived = cell || settings.space() == Space.CARTESIAN && !settings.logDistance();
        boolean sides = settings.sideWeight() > 0;
        penaltyAt = derived ? -1 : 2;
        additiveAt = derived ? 2 : 3;
        stride = additiveAt + (rows ? 1 : 0) + (sides ? 2 : 0);
        penaltyTimesScale = settings.penalty() * settings.penaltyScale();
        double[] classWeights = settings.weights().toArray();
        for (int group = 0; group < GROUPS; group++) {
            groupWeight[group] = classWeights[CLASS_OF_GROUP[group]] * (group == OWN_GOAL ? settings.ownGoalShare() : 1);
        }
        encoder = new ObjectSetEncoder(settings, groupWeight, stride, penaltyAt, additiveAt, rows, sides);
    }

    public Settings settings() {
        return settings;
    }

    /** Floats per object in the encoded and packed forms: 2 to 6 (see {@link Encoded}). */
    int stride() {
        return stride;
    }

    /** Where an object's additive coordinates start: from there to the stride, |differences| add to the pair cost. */
    int additiveAt() {
        return additiveAt;
    }

    boolean greedy() {
        return greedy;
    }

    /** Where the penalty is within an object's floats, -1 when it follows from the position. */
    int penaltyIndex() {
        return penaltyAt;
    }

    double groupWeight(int group) {
        return groupWeight[group];
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

    /**
     * The remembered previous scene as the memory term compares it: as {@link #encode(Scene, boolean)}
     * without memory, but with memory-direction-weight, since the direction that tells a turn from a dash
     * now may be noise one scene back.
     */
    Encoded encodePrevious(Scene previous) {
        return encoder.encodePrevious(previous);
    }

    Encoded encode(Scene scene, boolean withMemory) {
        return encoder.encode(scene, withMemory);
    }

    /** The action classes 1 .. memory-depth scenes back (-1 past the start of the remembered chain). */
    int[] rememberedActions(Scene scene) {
        return encoder.rememberedActions(scene);
    }

    /** Objects per group as {@link #encode} stores them, without placing them. */
    void count(Scene scene, int[] counts) {
        encoder.count(scene, counts);
    }

    /**
     * A scene's action as compared by memory: the primary type, with turns split by the sign of
     * the moment (left, straight, right), since the direction of a turn is what an agent repeats.
     */
    public static int actionClass(Scene scene) {
        int type = scene.actionType().ordinal();
        if (scene.actionType() != ActionType.TURN) {
            return type * 3;
        }
        return type * 3 + 1 + (int) Math.signum(scene.primaryAction().first());
    }

    @Override
    public double distance(Encoded query, Encoded stored, double bound) {
        if (workspace == null) {
            workspace = new Assignment.Workspace();
        }
        double total = 0;
        if (settings.memoryActionWeight() > 0) {
            total = actionsDistance(query.actions(), stored.actions(), 0);
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

    /**
     * The memory-action cost of two scenes' remembered action classes, the stored ones from
     * {@code at}: the i-th back costs memory-action · memory-decay^(i-1) when they differ. The one
     * sum every path computes, so distances are identical.
     */
    double actionsDistance(int[] query, int[] stored, int at) {
        double total = 0;
        double cost = settings.memoryActionWeight();
        for (int i = 0; i < query.length && at + i < stored.length; i++) {
            if (query[i] != stored[at + i]) {
                total += cost;
            }
            cost *= settings.memoryDecay();
        }
        return total;
    }

    int memoryDepth() {
        return settings.memoryActionWeight() > 0 ? settings.memoryDepth() : 0;
    }

    private static final Encoded EMPTY = new Encoded(new float[GROUPS][0], null, ObjectSetEncoder.NO_ACTIONS);

    private double groupsDistance(Encoded query, Encoded stored, double total, double bound, double scale) {
        for (int group = 0; group < GROUPS; group++) {
            if (groupWeight[group] == 0) {
                continue;
            }
            double weight = scale * groupWeight[group];
            float[] x = query.groups()[group];
            float[] y = stored.groups()[group];
            total += weight * groupDistance(x, 0, x.length / stride, y, 0, y.length / stride, total, weight, bound, workspace);
            if (total > bound) {
                return total;
            }
        }
        return total;
    }

    /**
     * Cost of pairing the objects at x[i] and y[j]. The straight-line distance is computed in
     * single precision, as precise as the stored floats and much faster to take the root of;
     * sums are in double.
     */
    double pairCost(float[] x, int i, float[] y, int j) {
        double cost;
        if (polar) {
            cost = Math.abs((double) x[i] - y[j]) + Math.abs((double) x[i + 1] - y[j + 1]);
        } else {
            float da = x[i] - y[j];
            float db = x[i + 1] - y[j + 1];
            cost = (float) Math.sqrt(da * da + db * db);
        }
        for (int c = additiveAt; c < stride; c++) {
            cost += Math.abs((double) x[i + c] - y[j + c]);
        }
        return cost;
    }

    /**
     * The penalty of the object at x[i]: P L / (L + d). Stored as a float where d is the
     * distance before log or weighting; in cartesian space without log-distance d is the
     * stored position's distance from the observer ({@link #radial}, single precision), in
     * cell space its row, so there it is computed from the position and takes no room.
     */
    double penalty(float[] x, int i) {
        if (penaltyAt >= 0) {
            return x[i + penaltyAt];
        }
        return penaltyAt(radial(x, i));
    }

    /** True when {@link #penalty} is {@link #penaltyAt} of {@link #radial}. */
    boolean penaltyFollowsRadial() {
        return penaltyAt < 0;
    }

    double penaltyAt(double distance) {
        return penaltyTimesScale / (settings.penaltyScale() + distance);
    }

    /**
     * Distance between n objects of x from offset xs and m objects of y from offset ys, the one
     * computation behind every path (encoded, packed, scene). Once {@code before + weight * d}
     * is known to exceed {@code bound} for some d not above the distance, d is returned instead:
     * the caller then computes that same sum, above the bound, and drops the scene as the exact
     * distance would.
     */
    double groupDistance(float[] x, int xs, int n, float[] y, int ys, int m, double before, double weight,
                         double bound, Assignment.Workspace scratch) {
        if (n == 0 && m == 0) {
            return 0;
        }
        if (greedy) {
            return greedyDistance(x, xs, n, y, ys, m, before, weight, bound);
        }
        if (n <= 1 && m <= 1) {
            return singleDistance(x, xs, n, y, ys, m);
        }
        // pad the smaller side with "missing" entries that cost the other object's penalty
        int size = Math.max(n, m);
        double[] cost = scratch.cost(size);
        double[] xp = scratch.rowPenalties;
        double[] yp = scratch.columnPenalties;
        for (int i = 0; i < n; i++) {
            xp[i] = penalty(x, xs + i * stride);
        }
        for (int j = 0; j < m; j++) {
            yp[j] = penalty(y, ys + j * stride);
        }
        for (int i = 0; i < size; i++) {
            int row = i * size;
            int at = xs + i * stride;
            for (int j = 0; j < size; j++) {
                int to = ys + j * stride;
                double value;
                if (i < n && j < m) {
                    value = Math.min(pairCost(x, at, y, to), xp[i] + yp[j]);
                } else if (i < n) {
                    value = xp[i];
                } else if (j < m) {
                    value = yp[j];
                } else {
                    value = 0;
                }
                cost[row + j] = value;
            }
        }
        return Assignment.minimumCost(scratch, size, before, weight, bound);
    }

    /** Both sides in order of distance, paired in order; the longer side's rest pays penalties. */
    private double greedyDistance(float[] x, int xs, int n, float[] y, int ys, int m, double before, double weight, double bound) {
        double total = 0;
        int paired = Math.min(n, m);
        for (int k = 0; k < paired; k++) {
            total += pairCost(x, xs + k * stride, y, ys + k * stride);
            // the remaining terms are not negative: the sum can only grow
            if (before + weight * total > bound) {
                return total;
            }
        }
        for (int k = paired; k < n; k++) {
            total += penalty(x, xs + k * stride);
        }
        for (int k = paired; k < m; k++) {
            total += penalty(y, ys + k * stride);
        }
        return total;
    }

    /** Optimal matching of at most one object per side: a pair (at most both penalties) or a penalty. */
    double singleDistance(float[] x, int xs, int n, float[] y, int ys, int m) {
        if (n == 1 && m == 1) {
            return Math.min(pairCost(x, xs, y, ys), penalty(x, xs) + penalty(y, ys));
        }
        return n == 1 ? penalty(x, xs) : m == 1 ? penalty(y, ys) : 0;
    }

    /**
     * A coordinate s of an object such that a pair's cost is at least |s(x) - s(y)| (up to
     * rounding, relatively less than 1e-6 of the coordinates): the radius in cartesian space (triangle inequality), a (the weighted distance)
     * in polar space, the row in cell space. Objects sorted by distance are (nearly) sorted by it.
     */
    double radial(float[] x, int i) {
        if (polar) {
            return x[i];
        }
        return cell ? x[i + 1] : (float) Math.sqrt(x[i] * x[i] + x[i + 1] * x[i + 1]);
    }

    /**
     * The knowledge base in one flat float array, scene after scene, each scene's groups in
     * order, each group's objects nearest first; per scene its start and its objects per group:
     * no object per scene or per object; with memory-action, each scene's remembered action
     * classes too. Not for the memory weight, which compares previous scenes' objects.
     * Configurations whose weighted groups hold at most one object per scene (ball, goals), with
     * or without memory terms, get the exact {@link LowDimensionalIndex} instead (unless
     * {@code index=false}).
     */
    @Override
    public PackedScenes pack(List<Scene> scenes) {
        // the index compares one previous action only
        if (indexed && (settings.memoryDepth() == 1 || settings.memoryActionWeight() == 0)) {
            LowDimensionalIndex index = LowDimensionalIndex.build(this, scenes);
            if (index != null) {
                return index;
            }
        }
        if (settings.memoryWeight() > 0) {
            return null;
        }
        return PackedObjectSets.pack(this, scenes);
    }
}
