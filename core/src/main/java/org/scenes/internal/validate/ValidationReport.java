package org.scenes.internal.validate;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionType;
import org.scenes.api.Scene;

/**
 * What one validation run measured. Action types are compared on the primary action; a
 * selector that finds no usable action predicts {@code none}. Parameter errors are taken over
 * the scenes where predicted and true types agree. Beside it, every {@link ActionLabel} (body,
 * neck, both) is scored with two baselines a result must beat to mean anything: the training
 * set's majority class, and repeating the previous test scene's recorded action.
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
    private final double p50Micros;
    private final double p99Micros;
    private final double maxMicros;
    private final Action[] truth;
    private final Action[] predicted;
    private final long[] nanos;
    /** [label ordinal][scene]: the recorded class, the predicted one, and the baselines' (null when unknown). */
    private final String[][] truthLabels;
    private final String[][] predictedLabels;
    private final String[][] majorityLabels;
    private final String[][] previousLabels;
    private final List<List<Action>> truthActions;
    private final List<List<Action>> predictedActions;
    private final Mean dashDirectionError = new Mean();
    private final Mean neckAngleError = new Mean();

    private ValidationReport(int trainScenes, Action[] truth, Action[] predicted, long[] nanos,
                             List<List<Action>> truthActions, List<List<Action>> predictedActions,
                             String[][] majorityLabels, String[][] previousLabels) {
        this.trainScenes = trainScenes;
        this.truth = truth;
        this.predicted = predicted;
        this.nanos = nanos;
        this.majorityLabels = majorityLabels;
        this.previousLabels = previousLabels;
        this.truthActions = truthActions;
        this.predictedActions = predictedActions;
        ActionLabel[] labels = ActionLabel.values();
        truthLabels = new String[labels.length][truth.length];
        predictedLabels = new String[labels.length][truth.length];
        for (int i = 0; i < truth.length; i++) {
            List<Action> t = truthActions.get(i);
            List<Action> p = predictedActions.get(i);
            for (ActionLabel label : labels) {
                truthLabels[label.ordinal()][i] = label.of(t);
                predictedLabels[label.ordinal()][i] = label.of(p);
            }
            Action bodyTruth = ActionLabel.bodyAction(t);
            Action bodyPredicted = ActionLabel.bodyAction(p);
            if (bodyTruth != null && bodyPredicted != null && bodyTruth.type() == ActionType.DASH
                    && bodyPredicted.type() == ActionType.DASH) {
                // a dash without direction goes straight ahead
                dashDirectionError.addAngle(orZero(bodyTruth.second()), orZero(bodyPredicted.second()));
            }
            Action neckTruth = ActionLabel.neckAction(t);
            Action neckPredicted = ActionLabel.neckAction(p);
            if (neckTruth != null && neckPredicted != null) {
                neckAngleError.add(neckTruth.first(), neckPredicted.first());
            }
        }
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
            boolean directionRight = rightWithDirection(i);
            switch (t) {
                case TURN -> {
                    turnPairs++;
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
        p50Micros = micros.length == 0 ? 0 : micros[Math.max(0, (int) Math.ceil(0.5 * micros.length) - 1)];
        p99Micros = micros.length == 0 ? 0 : micros[Math.min(micros.length - 1, (int) Math.ceil(0.99 * micros.length) - 1)];
        maxMicros = micros.length == 0 ? 0 : micros[micros.length - 1];
    }

    /** A report on primary actions only, without baselines (they need the training and test scenes). */
    public static ValidationReport of(int trainScenes, Action[] truth, Action[] predicted, long[] nanos) {
        return new ValidationReport(trainScenes, truth, predicted, nanos, singletons(truth), singletons(predicted),
                null, null);
    }

    /**
     * A report with every label and both baselines.
     *
     * @param train the training scenes (their majority class is the first baseline)
     * @param test the test scenes in recorded order (the previous one's action is the second baseline;
     *             a scene whose observer differs from the one before, or whose cycle is earlier, starts
     *             a new sequence and has no previous action)
     * @param predicted the predicted actions of each test scene, primary first (empty: none)
     */
    public static ValidationReport of(List<Scene> train, List<Scene> test, List<List<Action>> predicted, long[] nanos) {
        int n = test.size();
        Action[] truthPrimary = new Action[n];
        Action[] predictedPrimary = new Action[n];
        List<List<Action>> truthActions = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            truthActions.add(test.get(i).actions());
            truthPrimary[i] = test.get(i).primaryAction();
            predictedPrimary[i] = predicted.get(i).isEmpty() ? null : predicted.get(i).get(0);
        }
        ActionLabel[] labels = ActionLabel.values();
        String[][] majority = new String[labels.length][n];
        String[][] previous = new String[labels.length][n];
        for (ActionLabel label : labels) {
            Map<String, Integer> counts = new TreeMap<>();
            for (Scene scene : train) {
                counts.merge(label.of(scene.actions()), 1, Integer::sum);
            }
            String most = counts.entrySet().stream().max(Map.Entry.<String, Integer>comparingByValue()
                    .thenComparing(Map.Entry.comparingByKey(Comparator.reverseOrder())))
                    .map(Map.Entry::getKey).orElse(label.of(List.of()));
            Arrays.fill(majority[label.ordinal()], most);
            for (int i = 0; i < n; i++) {
                Scene before = i == 0 ? null : test.get(i - 1);
                boolean continues = before != null && before.observer().equals(test.get(i).observer())
                        && before.cycle() <= test.get(i).cycle();
                previous[label.ordinal()][i] = label.of(continues ? before.actions() : List.of());
            }
        }
        return new ValidationReport(train.size(), truthPrimary, predictedPrimary, nanos, truthActions, predicted,
                majority, previous);
    }

    private static List<List<Action>> singletons(Action[] actions) {
        List<List<Action>> lists = new ArrayList<>(actions.length);
        for (Action action : actions) {
            lists.add(action == null ? List.of() : List.of(action));
        }
        return lists;
    }

    private static double orZero(double value) {
        return Double.isNaN(value) ? 0 : value;
    }

    /**
     * One report over the decisions of several runs (e.g. the folds of a cross-validation), so
     * rare actions are counted over all of them rather than averaged from a few per run. Its
     * training size is the mean of the runs'.
     */
    public static ValidationReport pooled(List<ValidationReport> reports) {
        int total = reports.stream().mapToInt(r -> r.testScenes).sum();
        Action[] truth = new Action[total];
        Action[] predicted = new Action[total];
        long[] nanos = new long[total];
        List<List<Action>> truthActions = new ArrayList<>(total);
        List<List<Action>> predictedActions = new ArrayList<>(total);
        boolean baselines = reports.stream().allMatch(r -> r.majorityLabels != null);
        int labels = ActionLabel.values().length;
        String[][] majority = baselines ? new String[labels][total] : null;
        String[][] previous = baselines ? new String[labels][total] : null;
        int at = 0;
        long train = 0;
        for (ValidationReport report : reports) {
            System.arraycopy(report.truth, 0, truth, at, report.testScenes);
            System.arraycopy(report.predicted, 0, predicted, at, report.testScenes);
            System.arraycopy(report.nanos, 0, nanos, at, report.testScenes);
            truthActions.addAll(report.truthActions);
            predictedActions.addAll(report.predictedActions);
            if (baselines) {
                for (int label = 0; label < labels; label++) {
                    System.arraycopy(report.majorityLabels[label], 0, majority[label], at, report.testScenes);
                    System.arraycopy(report.previousLabels[label], 0, previous[label], at, report.testScenes);
                }
            }
            at += report.testScenes;
            train += report.trainScenes;
        }
        return new ValidationReport(reports.isEmpty() ? 0 : (int) (train / reports.size()), truth, predicted, nanos,
                truthActions, predictedActions, majority, previous);
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

        /** The difference of two directions in degrees, the short way round (0 to 180). */
        void addAngle(double truth, double predicted) {
            double difference = Math.abs(Math.IEEEremainder(truth - predicted, 360));
            sum += difference;
            count++;
        }

        double value() {
            return count == 0 ? Double.NaN : sum / count;
        }
    }

    /** Whether test scene {@code i}'s primary type was predicted. */
    public boolean right(int i) {
        return typeOf(truth[i]) == typeOf(predicted[i]);
    }

    /** Whether test scene {@code i}'s primary type was predicted, and for a turn the sign of its moment. */
    public boolean rightWithDirection(int i) {
        if (!right(i)) {
            return false;
        }
        return typeOf(truth[i]) != ActionType.TURN || Math.signum(truth[i].first()) == Math.signum(predicted[i].first());
    }

    /** Each test scene's recorded actions, in test order. */
    public List<List<Action>> recorded() {
        return Collections.unmodifiableList(truthActions);
    }

    /** Each test scene's predicted actions, primary first (empty: none), in test order. */
    public List<List<Action>> predictions() {
        return Collections.unmodifiableList(predictedActions);
    }

    /** Each test scene's decision time in nanoseconds, in test order. */
    public long[] decisionNanos() {
        return nanos.clone();
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

    /** Share of test scenes whose class by {@code label} was predicted right. */
    public double accuracy(ActionLabel label) {
        return share(predictedLabels[label.ordinal()], label);
    }

    /** Accuracy of always predicting the training set's most common class; NaN when unknown. */
    public double majorityBaseline(ActionLabel label) {
        return majorityLabels == null ? Double.NaN : share(majorityLabels[label.ordinal()], label);
    }

    /** The training set's most common class (of the first run, when pooled), or null when unknown. */
    public String majorityClass(ActionLabel label) {
        return majorityLabels == null || testScenes == 0 ? null : majorityLabels[label.ordinal()][0];
    }

    /** Accuracy of repeating the previous test scene's recorded action; NaN when unknown. */
    public double repeatPreviousBaseline(ActionLabel label) {
        return previousLabels == null ? Double.NaN : share(previousLabels[label.ordinal()], label);
    }

    /** Test scenes by recorded class of {@code label}, most common first. */
    public Map<String, Integer> classCounts(ActionLabel label) {
        Map<String, Integer> counts = new TreeMap<>();
        for (String value : truthLabels[label.ordinal()]) {
            counts.merge(value, 1, Integer::sum);
        }
        Map<String, Integer> sorted = new LinkedHashMap<>();
        counts.entrySet().stream().sorted(Map.Entry.<String, Integer>comparingByValue().reversed())
                .forEach(e -> sorted.put(e.getKey(), e.getValue()));
        return sorted;
    }

    private double share(String[] guesses, ActionLabel label) {
        if (testScenes == 0) {
            return Double.NaN;
        }
        String[] truthOf = truthLabels[label.ordinal()];
        int right = 0;
        for (int i = 0; i < testScenes; i++) {
            if (truthOf[i].equals(guesses[i])) {
                right++;
            }
        }
        return (double) right / testScenes;
    }

    /** Mean difference of dash directions (degrees, plain dashes count as 0) where both body actions are dashes. */
    public double dashDirectionError() {
        return dashDirectionError.value();
    }

    /** Mean difference of neck angles where both turned the neck ({@code turn_neck 0} included). */
    public double neckAngleError() {
        return neckAngleError.value();
    }

    public double meanDecisionMicros() {
        return meanMicros;
    }

    /** The median (nearest rank) of the same decisions the mean is over: a typical decision's time. */
    public double p50DecisionMicros() {
        return p50Micros;
    }

    /**
     * The 99th percentile (nearest rank) of the same decisions the mean is over: the mean can lie
     * above it when under 1 % of them are very slow (JIT warm-up, a garbage collection); see the max.
     */
    public double p99DecisionMicros() {
        return p99Micros;
    }

    /** The slowest of the timed decisions. */
    public double maxDecisionMicros() {
        return maxMicros;
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
        Map<String, Object> labels = new LinkedHashMap<>();
        for (ActionLabel label : ActionLabel.values()) {
            Map<String, Object> entry = new LinkedHashMap<>();
            entry.put("accuracy", number(accuracy(label)));
            entry.put("majorityBaseline", number(majorityBaseline(label)));
            entry.put("majorityClass", majorityClass(label));
            entry.put("repeatPreviousBaseline", number(repeatPreviousBaseline(label)));
            entry.put("classes", classCounts(label));
            labels.put(label.figure(), entry);
        }
        // every accuracy with the baselines it must beat (accuracy itself is labels.accuracy.accuracy)
        map.put("labels", labels);
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
        parameters.put("dashDirectionError", number(dashDirectionError()));
        parameters.put("neckAngleError", number(neckAngleError()));
        map.put("parameters", parameters);
        Map<String, Object> time = new LinkedHashMap<>();
        time.put("mean", number(meanDecisionMicros()));
        time.put("p50", number(p50DecisionMicros()));
        time.put("p99", number(p99DecisionMicros()));
        time.put("max", number(maxDecisionMicros()));
        time.put("decisions", testScenes);
        map.put("decisionMicros", time);
        map.put("scenesPer100ms", scenesPer100ms());
        return map;
    }

    static Object number(double value) {
        return Double.isNaN(value) || Double.isInfinite(value) ? null : value;
    }
}
