package org.scenes.plugins.ballgoal;

import java.util.List;
import org.scenes.match.PackedMetric;
import org.scenes.match.TopK;
import org.scenes.scene.Scene;

/**
 * The knowledge base for {@code ball-goal} as eight float columns (presence, column, row and
 * direction of ball and goal), scanned in blocks: a branch-free pass computes a block of
 * distances, a second pass offers those below the current k-th best. Arithmetic is done in
 * double in the order {@link BallGoalMetricProvider.BallGoalMetric#distance} uses, and packing
 * is refused unless every value is exact as a float, so distances are identical to the scan's.
 */
final class PackedBallGoal implements PackedMetric.PackedScenes {
    private static final int BLOCK = 512;

    private final BallGoalMetricProvider.BallGoalMetric metric;
    private final float[][] columns = new float[8][];
    private final int size;

    private PackedBallGoal(BallGoalMetricProvider.BallGoalMetric metric, int size) {
        this.metric = metric;
        this.size = size;
        for (int c = 0; c < 8; c++) {
            columns[c] = new float[size];
        }
    }

    /** The packed form, or null when a value would change as a float. */
    static PackedBallGoal pack(BallGoalMetricProvider.BallGoalMetric metric, List<Scene> scenes) {
        PackedBallGoal packed = new PackedBallGoal(metric, scenes.size());
        for (int i = 0; i < scenes.size(); i++) {
            double[] features = metric.encode(scenes.get(i));
            for (int c = 0; c < 8; c++) {
                float value = (float) features[c];
                if (value != features[c]) {
                    return null;
                }
                packed.columns[c][i] = value;
            }
        }
        return packed;
    }

    @Override
    public void scan(Scene query, TopK top) {
        double[] q = metric.encode(query);
        double ballWeight = metric.ballWeight();
        double goalWeight = metric.goalWeight();
        double[] block = new double[BLOCK];
        for (int start = 0; start < size; start += BLOCK) {
            int end = Math.min(size, start + BLOCK);
            distances(q, start, end, ballWeight, goalWeight, block);
            double bound = top.bound();
            for (int i = start; i < end; i++) {
                double distance = block[i - start];
                if (distance < bound) {
                    top.offer(distance, i);
                    bound = top.bound();
                }
            }
        }
    }

    private void distances(double[] q, int start, int end, double ballWeight, double goalWeight, double[] block) {
        double cw = metric.columnWeight();
        double rw = metric.rowWeight();
        double aw = metric.anglePerDegree();
        double missing = metric.missing();
        double cap = 2 * missing;
        double qbp = q[0];
        double qbc = q[1];
        double qbr = q[2];
        double qbd = q[3];
        double qgp = q[4];
        double qgc = q[5];
        double qgr = q[6];
        double qgd = q[7];
        float[] bp = columns[0];
        float[] bc = columns[1];
        float[] br = columns[2];
        float[] bd = columns[3];
        float[] gp = columns[4];
        float[] gc = columns[5];
        float[] gr = columns[6];
        float[] gd = columns[7];
        for (int i = start; i < end; i++) {
            // presence is 0 or 1, so these products select a case exactly, without branches
            double p = bp[i];
            double cost = Math.min(cw * Math.abs(qbc - bc[i]) + rw * Math.abs(qbr - br[i]) + aw * Math.abs(qbd - bd[i]), cap);
            double ball = qbp * (p * cost + (1 - p) * missing) + (1 - qbp) * (p * missing);
            p = gp[i];
            cost = Math.min(cw * Math.abs(qgc - gc[i]) + rw * Math.abs(qgr - gr[i]) + aw * Math.abs(qgd - gd[i]), cap);
            double goal = qgp * (p * cost + (1 - p) * missing) + (1 - qgp) * (p * missing);
            block[i - start] = ballWeight * ball + goalWeight * goal;
        }
    }
}
