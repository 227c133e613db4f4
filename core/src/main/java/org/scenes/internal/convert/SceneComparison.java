package org.scenes.internal.convert;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import org.scenes.api.Action;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.scene.SceneFileReader;

/**
 * How close two scene files of one player are, e.g. scenes rebuilt from a game log against those
 * converted from the player's own log: scenes of the same cycle are paired (within a cycle, the
 * last with the last, as a standing clock repeats a cycle), and in each pair the objects are
 * matched by kind and name (a player also by team and number where both scenes read them; among
 * equals, the nearest in direction). Streams both files.
 */
public final class SceneComparison {
    /** Errors are counted in steps of this size (distances in metres, directions in degrees). */
    private static final int HISTOGRAM = 4096;

    /**
     * The figures of a comparison.
     *
     * @param scenesA scenes in the first file
     * @param scenesB scenes in the second
     * @param paired scenes of the same cycle in both
     * @param objectsA objects of the paired scenes, first file
     * @param objectsB objects of the paired scenes, second file
     * @param matched objects present in both
     * @param distanceWithinStep matched objects whose distances differ by at most one quantisation step
     * @param distances matched objects with a distance on both sides
     * @param directionWithinStep matched objects whose directions differ by at most one degree
     * @param actionTypeAgrees paired scenes whose primary actions have the same type
     * @param actionAgrees paired scenes whose actions are the same commands
     */
    public record Result(Observer observerA, Observer observerB, long scenesA, long scenesB, long paired,
                         long objectsA, long objectsB, long matched, long distances, long distanceWithinStep,
                         double distanceErrorMean, double distanceErrorP99, double distanceErrorMax,
                         long directions, long directionWithinStep, double directionErrorMean,
                         double directionErrorP99, double directionErrorMax, long actionTypeAgrees,
                         long actionAgrees) {
        /** Matched objects as a share of those in either scene of a pair. */
        public double matchedShare() {
            long union = objectsA + objectsB - matched;
            return union == 0 ? 1 : (double) matched / union;
        }

        public double distanceWithinStepShare() {
            return distances == 0 ? 1 : (double) distanceWithinStep / distances;
        }

        public double directionWithinStepShare() {
            return directions == 0 ? 1 : (double) directionWithinStep / directions;
        }

        public double actionTypeShare() {
            return paired == 0 ? 0 : (double) actionTypeAgrees / paired;
        }

        public double actionShare() {
            return paired == 0 ? 0 : (double) actionAgrees / paired;
        }
    }

    private final double quantizeStep;
    private final double quantizeStepL;

    /** Quantisation of the server's defaults: 0.1 for moving objects, 0.01 for landmarks and lines. */
    public SceneComparison() {
        this(0.1, 0.01);
    }

    public SceneComparison(double quantizeStep, double quantizeStepL) {
        this.quantizeStep = quantizeStep;
        this.quantizeStepL = quantizeStepL;
    }

    public Result compare(Path a, Path b) {
        return compare(List.of(a), List.of(b));
    }

    /**
     * Compares {@code a.get(i)} with {@code b.get(i)} for each i (e.g. every player of a game) and
     * sums the figures; the observers are those of the first pair.
     */
    public Result compare(List<Path> a, List<Path> b) {
        if (a.size() != b.size() || a.isEmpty()) {
            throw new IllegalArgumentException("compare pairs of files: " + a.size() + " against " + b.size());
        }
        Tally tally = new Tally();
        Observer observerA = null;
        Observer observerB = null;
        long scenesA = 0;
        long scenesB = 0;
        for (int i = 0; i < a.size(); i++) {
            try (SceneFileReader first = SceneFileReader.open(a.get(i));
                 SceneFileReader second = SceneFileReader.open(b.get(i))) {
                Cycles left = new Cycles(first);
                Cycles right = new Cycles(second);
                pairCycles(tally, left, right);
                if (observerA == null) {
                    observerA = first.header().source().observer();
                    observerB = second.header().source().observer();
                }
                scenesA += left.count;
                scenesB += right.count;
            }
        }
        return tally.result(observerA, observerB, scenesA, scenesB);
    }

    private static void pairCycles(Tally tally, Cycles left, Cycles right) {
        List<Scene> x = left.next();
        List<Scene> y = right.next();
        while (x != null && y != null) {
            int cx = x.get(0).cycle();
            int cy = y.get(0).cycle();
            if (cx < cy) {
                x = left.next();
            } else if (cy < cx) {
                y = right.next();
            } else {
                int n = Math.min(x.size(), y.size());
                for (int i = 1; i <= n; i++) {
                    tally.pair(x.get(x.size() - i), y.get(y.size() - i));
                }
                x = left.next();
                y = right.next();
            }
        }
        while (x != null) {
            x = left.next();
        }
        while (y != null) {
            y = right.next();
        }
    }

    /** A file's scenes grouped by cycle, in file order. */
    private static final class Cycles {
        final SceneFileReader reader;
        Scene pending;
        long count;

        Cycles(SceneFileReader reader) {
            this.reader = reader;
        }

        List<Scene> next() {
            if (pending == null && !reader.hasNext()) {
                return null;
            }
            List<Scene> group = new ArrayList<>();
            Scene scene = pending != null ? pending : read();
            pending = null;
            group.add(scene);
            while (reader.hasNext()) {
                Scene following = read();
                if (following.cycle() != scene.cycle()) {
                    pending = following;
                    break;
                }
                group.add(following);
            }
            return group;
        }

        private Scene read() {
            count++;
            return reader.next();
        }
    }

    private final class Tally {
        long paired;
        long objectsA;
        long objectsB;
        long matched;
        long typeAgrees;
        long actionAgrees;
        final Errors distance = new Errors(0.01);
        final Errors direction = new Errors(0.5);
        long distanceWithin;
        long directionWithin;

        void pair(Scene a, Scene b) {
            paired++;
            List<SeenObject> left = a.objects();
            List<SeenObject> right = b.objects();
            objectsA += left.size();
            objectsB += right.size();
            boolean[] taken = new boolean[right.size()];
            for (SeenObject object : left) {
                int best = -1;
                double bestGap = Double.POSITIVE_INFINITY;
                for (int j = 0; j < right.size(); j++) {
                    SeenObject other = right.get(j);
                    if (taken[j] || !same(object, other)) {
                        continue;
                    }
                    double gap = angleGap(object.direction(), other.direction());
                    if (!(gap >= bestGap)) {
                        best = j;
                        bestGap = gap;
                    }
                }
                if (best < 0) {
                    continue;
                }
                taken[best] = true;
                matched++;
                SeenObject other = right.get(best);
                if (!Double.isNaN(object.distance()) && !Double.isNaN(other.distance())) {
                    double error = Math.abs(object.distance() - other.distance());
                    distance.add(error);
                    if (error <= step(object) + 1e-6) {
                        distanceWithin++;
                    }
                }
                if (!Double.isNaN(object.direction()) && !Double.isNaN(other.direction())) {
                    double error = angleGap(object.direction(), other.direction());
                    direction.add(error);
                    if (error <= 1 + 1e-6) {
                        directionWithin++;
                    }
                }
            }
            if (a.actionType() == b.actionType()) {
                typeAgrees++;
            }
            if (sameActions(a.actions(), b.actions())) {
                actionAgrees++;
            }
        }

        /** One quantisation step of a seen distance: the log-domain step, then the decimetre. */
        double step(SeenObject object) {
            double q = object.kind() == ObjectKind.BALL || object.kind() == ObjectKind.PLAYER ? quantizeStep
                    : quantizeStepL;
            return Math.max(0.1, object.distance() * (Math.exp(q) - 1)) + 0.05;
        }

        Result result(Observer observerA, Observer observerB, long scenesA, long scenesB) {
            return new Result(observerA, observerB, scenesA, scenesB, paired, objectsA, objectsB, matched,
                    distance.count, distanceWithin, distance.mean(), distance.quantile(0.99), distance.max,
                    direction.count, directionWithin, direction.mean(), direction.quantile(0.99), direction.max,
                    typeAgrees, actionAgrees);
        }
    }

    static boolean same(SeenObject a, SeenObject b) {
        if (a.kind() != b.kind() || !a.name().equals(b.name())) {
            return false;
        }
        if (a.kind() != ObjectKind.PLAYER) {
            return true;
        }
        if (!a.team().isEmpty() && !b.team().isEmpty() && !a.team().equals(b.team())) {
            return false;
        }
        return a.uniformNumber() == 0 || b.uniformNumber() == 0 || a.uniformNumber() == b.uniformNumber();
    }

    static boolean sameActions(List<Action> a, List<Action> b) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0; i < a.size(); i++) {
            if (!Objects.equals(a.get(i).describe(), b.get(i).describe())) {
                return false;
            }
        }
        return true;
    }

    static double angleGap(double a, double b) {
        double gap = Math.abs(a - b) % 360;
        return gap > 180 ? 360 - gap : gap;
    }

    /** Absolute errors in a fixed-width histogram: mean, quantiles and maximum in bounded memory. */
    private static final class Errors {
        final double width;
        final long[] counts = new long[HISTOGRAM];
        long count;
        double sum;
        double max;

        Errors(double width) {
            this.width = width;
        }

        void add(double error) {
            count++;
            sum += error;
            max = Math.max(max, error);
            counts[(int) Math.min(HISTOGRAM - 1, Math.floor(error / width))]++;
        }

        double mean() {
            return count == 0 ? 0 : sum / count;
        }

        /** The upper edge of the bucket holding the quantile. */
        double quantile(double q) {
            if (count == 0) {
                return 0;
            }
            long wanted = (long) Math.ceil(q * count);
            long seen = 0;
            for (int i = 0; i < HISTOGRAM; i++) {
                seen += counts[i];
                if (seen >= wanted) {
                    return Math.min(max, (i + 1) * width);
                }
            }
            return max;
        }

        @Override
        public String toString() {
            return Arrays.toString(counts);
        }
    }
}
