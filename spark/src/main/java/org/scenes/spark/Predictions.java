package org.scenes.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.internal.validate.ValidationReport;

/**
 * What one (configuration, fold) task sends back: each test scene's predicted actions and decision
 * time, packed as numbers. The driver rebuilds the fold's {@link ValidationReport} from them and the
 * scenes it holds, so every figure is computed by the validator's own code.
 */
final class Predictions implements Serializable {
    private static final ActionType[] TYPES = ActionType.values();

    final int task;
    private final byte[] counts;
    private final byte[] types;
    private final double[] first;
    private final double[] second;
    private final long[] nanos;

    private Predictions(int task, byte[] counts, byte[] types, double[] first, double[] second, long[] nanos) {
        this.task = task;
        this.counts = counts;
        this.types = types;
        this.first = first;
        this.second = second;
        this.nanos = nanos;
    }

    static Predictions of(int task, ValidationReport report) {
        List<List<Action>> predicted = report.predictions();
        int total = predicted.stream().mapToInt(List::size).sum();
        byte[] counts = new byte[predicted.size()];
        byte[] types = new byte[total];
        double[] first = new double[total];
        double[] second = new double[total];
        int at = 0;
        for (int i = 0; i < predicted.size(); i++) {
            List<Action> actions = predicted.get(i);
            counts[i] = (byte) actions.size();
            for (Action action : actions) {
                types[at] = (byte) action.type().ordinal();
                first[at] = action.first();
                second[at] = action.second();
                at++;
            }
        }
        return new Predictions(task, counts, types, first, second, report.decisionNanos());
    }

    List<List<Action>> actions() {
        List<List<Action>> actions = new ArrayList<>(counts.length);
        int at = 0;
        for (byte count : counts) {
            List<Action> scene = new ArrayList<>(count);
            for (int j = 0; j < count; j++, at++) {
                scene.add(new Action(TYPES[types[at]], first[at], second[at]));
            }
            actions.add(List.copyOf(scene));
        }
        return actions;
    }

    long[] nanos() {
        return nanos;
    }

    int queries() {
        return counts.length;
    }
}
