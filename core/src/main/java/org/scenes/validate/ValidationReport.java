package org.scenes.validate;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.scene.Action;
import org.scenes.scene.ActionType;

/**
 * What one validation run measured. Action types are compared on the primary action; a
 * selector that finds no usable action predicts {@code none}. Parameter errors are taken over
 * the scenes where predicted and true types agree.
 */
public final class ValidationReport {
    private final int trainScenes;
    private final int testScenes;
    private final int[][] confusion; // [true type][predicted type], over ActionType ordinals
    private final int directionCorrect;
    private final Mean turnMomentError = new Mean();
    private final Mean dashPowerError = new Mean();
    private final Mean kickPowerError = new Mean();
    private final Mean kickDirectionError = new Mean();
    private int turnPairs;
    private int turnSignAgree;
    private final double meanMicros;
    private final double p99Micros;
    private final Action[] truth;
    private final Action[] predicted;
    private final long[] nanos;

    private ValidationReport(int trainScenes, Action[] truth, Action[] predicted, long[] nanos) {
        this.trainScenes = trainScenes;
        this.truth = truth;
        this.predicted = predicted;
        this.nanos = nanos;
        this.testScenes = truth.length;
        int types = ActionType.values().length;
        confusion = new int[types][types];
        int withDirection = 0;
        for (int i = 0; i < truth.length; i++) {
            ActionType t = typeOf(truth[i]);
            ActionType p = typeOf(predicted[i]);
            confusion[t.ordinal()][p.ordinal()]++;
            if (t != p) {
                continue;
            }
            boolean directionRight = true;
            switch (t) {
                case TURN -> {
                    turnPairs++;
                    directionRight = Math.signum(truth[i].first()) == Math.signum(predicted[i].first());
                    if (directionRight) {
                        turnSignAgree++;
                    }
                    turnMomentError.add(truth[i].first(), predicted[i].first());
                }
                case DASH -> dashPowerError.add(truth[i].first(), predicted[i].first());
                case KICK -> {
                    kickPowerError.add(truth[i].first(), predicted[i].first());
                    kickDirectionError.add(truth[i].second(), predicted[i].second());
                }
                default -> {
                }
            }
            if (directionRight) {
                withDirection++;
            }
        }
        directionCorrect = withDirection;
        double[] micros = Arrays.stream(nanos).mapToDouble(n -> n / 1000.0).sorted().toArray();
        meanMicros = micros.length == 0 ? 0 : Arrays.stream(micros).average().orElse(0);
        p99Micros = micros.length == 0 ? 0 : micros[Math.min(micros.length - 1, (int) Math.ceil(0.99 * micros.length) - 1)];
    }

    public static ValidationReport of(int trainScenes, Action[] truth, Action[] predicted, long[] nanos) {
        return new ValidationReport(trainScenes, truth, predicted, nanos);
    }

    /**
     * One report over the decisions of several runs (e.g. the folds of a cross-validation), so
     * rare actions are counted over all of them rather than averaged from a few per run. Its
     * training size is the mean of the runs'.
     */
    public static ValidationReport pooled(java.util.List<ValidationReport> reports) {
        int total = reports.stream().mapToInt(r -> r.testScenes).sum();
        Action[] truth = new Action[total];
        Action[] predicted = new Action[total];
        long[] nanos = new long[total];
        int at = 0;
        long train = 0;
        for (ValidationReport report : reports) {
            System.arraycopy(report.truth, 0, truth, at, report.testScenes);
            System.arraycopy(report.predicted, 0, predicted, at, report.testScenes);
            System.arraycopy(report.nanos, 0, nanos, at, report.testScenes);
            at += report.testScenes;
            train += report.trainScenes;
        }
        return new ValidationReport(reports.isEmpty() ? 0 : (int) (train / reports.size()), truth, predicted, nanos);
    }

    private static ActionType typeOf(Action action) {
        return action == null ? ActionType.NONE : action.type();
    }

    /** Mean absolute difference over pairs where both values were sent. */
    private static final class Mean {
        double sum;
        int count;

        void add(double truth, double predicted) {
            if (!Double.isNaN(truth) && !Double.isNaN(predicted)) {
                sum += Math.abs(truth - predicted);
                count++;
            }
        }

        double value() {
            return count == 0 ? Double.NaN : sum / count;
        }
    }

    public int trainScenes() {
        return trainScenes;
    }

    public int testScenes() {
        return testScenes;
    }

    public int correct() {
        int correct = 0;
        for (int i = 0; i < confusion.length; i++) {
            correct += confusion[i][i];
        }
        return correct;
    }

    public double accuracy() {
        return testScenes == 0 ? Double.NaN : (double) correct() / testScenes;
    }

    /** Like accuracy, but a turn counts only when the moment's sign is also right. */
    public double directionAccuracy() {
        return testScenes == 0 ? Double.NaN : (double) directionCorrect / testScenes;
    }

    public int support(ActionType type) {
        return Arrays.stream(confusion[type.ordinal()]).sum();
    }

    public int predictedCount(ActionType type) {
        int count = 0;
        for (int[] row : confusion) {
            count += row[type.ordinal()];
        }
        return count;
    }

    public int truePositives(ActionType type) {
        return confusion[type.ordinal()][type.ordinal()];
    }

    public double precision(ActionType type) {
        int predicted = predictedCount(type);
        return predicted == 0 ? 0 : (double) truePositives(type) / predicted;
    }

    public double recall(ActionType type) {
        int support = support(type);
        return support == 0 ? Double.NaN : (double) truePositives(type) / support;
    }

    public double f1(ActionType type) {
        double p = precision(type);
        double r = recall(type);
        if (Double.isNaN(r)) {
            r = 0;
        }
        return p + r == 0 ? 0 : 2 * p * r / (p + r);
    }

    /** Action types that occur in the test scenes or the predictions. */
    public List<ActionType> types() {
        List<ActionType> types = new ArrayList<>();
        for (ActionType type : ActionType.values()) {
            if (support(type) > 0 || predictedCount(type) > 0) {
                types.add(type);
            }
        }
        return types;
    }

    /** Mean F1 over the types that occur in the test scenes (predicted-only types count as 0 there too). */
    public double macroF1() {
        List<ActionType> types = types();
        return types.isEmpty() ? Double.NaN : types.stream().mapToDouble(this::f1).average().orElse(Double.NaN);
    }

    public int confusion(ActionType truth, ActionType predicted) {
        return confusion[truth.ordinal()][predicted.ordinal()];
    }

    /** Share of turns (predicted and true) whose moments have the same sign. */
    public double turnSignAgreement() {
        return turnPairs == 0 ? Double.NaN : (double) turnSignAgree / turnPairs;
    }

    public double turnMomentError() {
        return turnMomentError.value();
    }

    public double dashPowerError() {
        return dashPowerError.value();
    }

    public double kickPowerError() {
        return kickPowerError.value();
    }

    public double kickDirectionError() {
        return kickDirectionError.value();
    }

    public double meanDecisionMicros() {
        return meanMicros;
    }

    public double p99DecisionMicros() {
        return p99Micros;
    }

    /** Stored scenes one decision could scan in a 100 ms cycle at the measured mean speed. */
    public long scenesPer100ms() {
        return meanMicros <= 0 ? 0 : (long) (trainScenes * 100_000.0 / meanMicros);
    }

    /** Plain maps, lists and numbers (NaN as null) for JSON output. */
    public Map<String, Object> toMap() {
        Map<String, Object> map = new LinkedHashMap<>();
        map.put("trainScenes", trainScenes);
        map.put("testScenes", testScenes);
        map.put("accuracy", number(accuracy()));
        map.put("directionAccuracy", number(directionAccuracy()));
        map.put("macroF1", number(macroF1()));
        Map<String, Object> kick = new LinkedHashMap<>();
        kick.put("total", support(ActionType.KICK));
        kick.put("correct", truePositives(ActionType.KICK));
        kick.put("predicted", predictedCount(ActionType.KICK));
        kick.put("recall", number(recall(ActionType.KICK)));
        kick.put("precision", number(precision(ActionType.KICK)));
        kick.put("f1", number(f1(ActionType.KICK)));
        map.put("kick", kick);
        Map<String, Object> perAction = new LinkedHashMap<>();
        for (ActionType type : types()) {
            Map<String, Object> entry = new LinkedHashMap<>();
            entry.put("support", support(type));
            entry.put("predicted", predictedCount(type));
            entry.put("correct", truePositives(type));
            entry.put("precision", number(precision(type)));
            entry.put("recall", number(recall(type)));
            entry.put("f1", number(f1(type)));
            perAction.put(type.key(), entry);
        }
        map.put("perAction", perAction);
        Map<String, Object> confusionMap = new LinkedHashMap<>();
        for (ActionType truth : types()) {
            Map<String, Object> row = new LinkedHashMap<>();
            for (ActionType predicted : types()) {
                row.put(predicted.key(), confusion(truth, predicted));
            }
            confusionMap.put(truth.key(), row);
        }
        map.put("confusion", confusionMap);
        Map<String, Object> parameters = new LinkedHashMap<>();
        parameters.put("turnSignAgreement", number(turnSignAgreement()));
        parameters.put("turnMomentError", number(turnMomentError()));
        parameters.put("dashPowerError", number(dashPowerError()));
        parameters.put("kickPowerError", number(kickPowerError()));
        parameters.put("kickDirectionError", number(kickDirectionError()));
        map.put("parameters", parameters);
        Map<String, Object> time = new LinkedHashMap<>();
        time.put("mean", number(meanDecisionMicros()));
        time.put("p99", number(p99DecisionMicros()));
        map.put("decisionMicros", time);
        map.put("scenesPer100ms", scenesPer100ms());
        return map;
    }

    static Object number(double value) {
        return Double.isNaN(value) || Double.isInfinite(value) ? null : value;
    }
}
