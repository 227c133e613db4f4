package org.scenes.internal.convert;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.Grid;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.vision.Landmarks;
import org.scenes.internal.vision.VisionNumbers;

/**
 * What a player did, as evidence for where its asynchronous see clock starts when the timing of
 * its commands does not tell (a player that acts on a clock of its own). Each candidate clock
 * pairs every see with the first body command after it, as scenes do; the candidate whose pairs
 * agree most with themselves wins: for each pair, whether the nearest other pair under the
 * {@code ball-goal} distance (the ball's and the opponent goal's cell and direction; docs/metrics.md)
 * has the same kind of command. A player acts on what it saw, so the true clock pairs alike
 * situations with alike commands; a clock a step off pairs commands with what the player saw a
 * step earlier or later.
 */
final class PhaseEvidence {
    /** {@code ball-goal}'s defaults: row and column weights, weight per degree, cost of a missing object. */
    private static final double ROW_WEIGHT = 3;
    private static final double COLUMN_WEIGHT = 1;
    private static final double ANGLE_WEIGHT = 0.05;
    private static final double MISSING = 10;

    private final List<Double> offsets;
    private final double simulatorStep;
    private final double visibleDistance;
    private final Grid grid = Grid.DEFAULT;
    /** The shows in order: the step their sees go out in, the see period, what would be seen. */
    private final List<Long> steps = new ArrayList<>();
    private final List<Double> periods = new ArrayList<>();
    private final List<float[]> seen = new ArrayList<>();
    /** The body commands, each with the number of shows before it and its kind. */
    private final List<Integer> commandShows = new ArrayList<>();
    private final List<CommandType> commandKinds = new ArrayList<>();

    PhaseEvidence(List<Double> offsets, double simulatorStep, double visibleDistance) {
        this.offsets = offsets;
        this.simulatorStep = simulatorStep;
        this.visibleDistance = visibleDistance;
    }

    /** A show whose sees (if the player's clock has one then) go out in {@code step}. */
    void show(long step, double period, PlayerState self, double ballX, double ballY) {
        steps.add(step);
        periods.add(period);
        seen.add(features(self, ballX, ballY));
    }

    /** A line the player sent after the shows given so far, by its first body command (null: none). */
    void command(CommandType firstBody) {
        if (firstBody != null) {
            commandShows.add(steps.size());
            commandKinds.add(firstBody);
        }
    }

    /** The candidate whose pairs agree most with themselves; the first unless another agrees more. */
    int best() {
        double[] scores = scores();
        int best = 0;
        for (int c = 1; c < scores.length; c++) {
            if (scores[c] > scores[best]) {
                best = c;
            }
        }
        return best;
    }

    /** Each candidate's share of agreeing pairs; candidates seeing in the same steps are scored once. */
    double[] scores() {
        double[] scores = new double[offsets.size()];
        Map<BitSet, Double> scored = new HashMap<>();
        for (int c = 0; c < offsets.size(); c++) {
            BitSet sees = new BitSet(steps.size());
            for (int s = 0; s < steps.size(); s++) {
                if (SeePhases.asynchSees(steps.get(s), periods.get(s), offsets.get(c), simulatorStep) > 0) {
                    sees.set(s);
                }
            }
            Double known = scored.get(sees);
            scores[c] = known != null ? known : agreement(sees);
            scored.put(sees, scores[c]);
        }
        return scores;
    }

    /**
     * Leave-one-out nearest-neighbour agreement of the pairs the see steps {@code sees} make, as a
     * share: a clock with a see more would otherwise win by its pair more.
     */
    private double agreement(BitSet sees) {
        List<float[]> situations = new ArrayList<>();
        List<CommandType> kinds = new ArrayList<>();
        int paired = -1;
        int lastCommand = -1;
        for (int i = 0; i < commandShows.size(); i++) {
            // the command's step is that of the last show before it; as the rebuilt logs order them
            // (Worker.commandsFirst), it answers the latest see of an earlier step when that see came
            // after its last command's step, else the see of its own step, if any
            int step = commandShows.get(i) - 1;
            if (step < 0) {
                continue; // sent before the first show
            }
            int see = sees.previousSetBit(step - 1);
            if (see <= lastCommand && sees.get(step)) {
                see = step;
            }
            lastCommand = step;
            if (see < 0 || see == paired) {
                continue;
            }
            paired = see;
            situations.add(seen.get(see));
            kinds.add(commandKinds.get(i));
        }
        int agree = 0;
        for (int i = 0; i < situations.size(); i++) {
            double nearest = Double.MAX_VALUE;
            int nearestAt = -1;
            float[] here = situations.get(i);
            for (int j = 0; j < situations.size() && nearest > 0; j++) {
                // nothing is nearer than 0, and of equals the first counts: the search can stop there
                if (j == i) {
                    continue;
                }
                double d = distance(here, situations.get(j));
                if (d < nearest) {
                    nearest = d;
                    nearestAt = j;
                }
            }
            if (nearestAt >= 0 && kinds.get(nearestAt) == kinds.get(i)) {
                agree++;
            }
        }
        return situations.isEmpty() ? 0 : (double) agree / situations.size();
    }

    private static double distance(float[] a, float[] b) {
        return object(a, b, 0) + object(a, b, 3);
    }

    private static double object(float[] a, float[] b, int at) {
        boolean inA = !Float.isNaN(a[at]);
        boolean inB = !Float.isNaN(b[at]);
        if (inA != inB) {
            return MISSING;
        }
        if (!inA) {
            return 0;
        }
        return Math.min(2 * MISSING, ROW_WEIGHT * Math.abs(a[at] - b[at])
                + COLUMN_WEIGHT * Math.abs(a[at + 1] - b[at + 1]) + ANGLE_WEIGHT * Math.abs(a[at + 2] - b[at + 2]));
    }

    /** The ball's and the opponent goal's row, column and whole-degree direction (NaN: not seen). */
    private float[] features(PlayerState self, double ballX, double ballY) {
        double head = VisionNumbers.normalize(self.body() + self.neck());
        double half = self.viewWidth() / 2;
        double goal = self.side() == Side.LEFT ? Landmarks.PITCH_HALF_LENGTH : -Landmarks.PITCH_HALF_LENGTH;
        float[] features = new float[6];
        // a ball behind within visible_distance is seen too, without its name
        object(features, 0, self, head, half, ballX, ballY, visibleDistance);
        object(features, 3, self, head, half, goal, 0, 0);
        return features;
    }

    private void object(float[] into, int at, PlayerState self, double head, double half, double x, double y,
                        double near) {
        double dx = x - self.x();
        double dy = y - self.y();
        double distance = Math.hypot(dx, dy);
        double direction = VisionNumbers.normalize(Math.toDegrees(Math.atan2(dy, dx)) - head);
        if (Math.abs(direction) < half || distance <= near) {
            into[at] = grid.row(distance);
            into[at + 1] = grid.column(direction);
            into[at + 2] = (float) Math.rint(direction);
        } else {
            into[at] = Float.NaN;
        }
    }
}
