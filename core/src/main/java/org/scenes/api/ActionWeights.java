package org.scenes.api;

import java.util.Arrays;

/**
 * Weights of action types for selectors, in the thesis' order none, dash, kick, turn_neck,
 * turn, catch, move (then tackle, 1 when not given). Written {@code 1/1/2/1/1/1/1} or by name,
 * {@code kick=2,turn_neck=0}, where types not named keep weight 1.
 */
public record ActionWeights(double[] weights) {
    /** Every action type weighs 1. */
    public static final ActionWeights DEFAULT = uniform();

    /**
     * Copies the weights and checks them: one per action type, finite and not negative.
     *
     * @param weights one weight per {@link ActionType}, in its order
     */
    public ActionWeights {
        if (weights.length != ActionType.values().length) {
            throw new IllegalArgumentException("action weights need " + ActionType.values().length + " values");
        }
        weights = weights.clone();
        for (double weight : weights) {
            if (!(weight >= 0) || Double.isInfinite(weight)) {
                throw new IllegalArgumentException("action weights must be finite and not negative");
            }
        }
    }

    private static ActionWeights uniform() {
        double[] weights = new double[ActionType.values().length];
        Arrays.fill(weights, 1);
        return new ActionWeights(weights);
    }

    /**
     * The weight of one type.
     *
     * @param type the action type
     * @return its weight
     */
    public double weight(ActionType type) {
        return weights[type.ordinal()];
    }

    /**
     * Reads the written form, positional or by name.
     *
     * @param text e.g. {@code 1/1/2/1/1/1/1} or {@code kick=2,turn_neck=0}
     * @return the weights; a malformed text is an {@code IllegalArgumentException}
     */
    public static ActionWeights parse(String text) {
        String[] names = new String[ActionType.values().length];
        for (ActionType type : ActionType.values()) {
            names[type.ordinal()] = type.key();
        }
        double[] parsed = Weights.parseWithDefault(text, names, "action weights", 1, ActionType.values().length - 1);
        return new ActionWeights(parsed);
    }

    /** @return a copy of the weights, one per action type in its order */
    @Override
    public double[] weights() {
        return weights.clone();
    }

    /**
     * The positional form, {@code 1/1/2/1/1/1/1/1}.
     *
     * @return the weights, slash-separated
     */
    public String format() {
        return Weights.format(weights);
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof ActionWeights that && Arrays.equals(weights, that.weights);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(weights);
    }

    @Override
    public String toString() {
        return format();
    }
}
