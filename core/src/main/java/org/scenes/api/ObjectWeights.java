package org.scenes.api;

/**
 * Weights of the eight object classes a metric sums over, in the thesis' order: ball, goal,
 * flag, line, all players (players matched regardless of team), teammates, opponents,
 * unknown players. Written {@code 1/0/1/1/0/1/1/1} (commas also work) or by name,
 * {@code ball=1,goal=1}, where classes not named weigh 0.
 */
public record ObjectWeights(double ball, double goal, double flag, double line,
                            double players, double teammates, double opponents, double unknownPlayers) {

    /** The names of the classes in the written form, in order. */
    public static final String[] NAMES = {"ball", "goal", "flag", "line", "players", "teammates", "opponents", "unknown"};

    /** Every class counts, players sorted by team relation. */
    public static final ObjectWeights DEFAULT = new ObjectWeights(1, 1, 1, 1, 0, 1, 1, 1);

    /**
     * Checks that every weight is finite and not negative.
     *
     * @param ball weight of the ball
     * @param goal weight of goals
     * @param flag weight of flags
     * @param line weight of lines
     * @param players weight of all players, matched regardless of team
     * @param teammates weight of teammates
     * @param opponents weight of opponents
     * @param unknownPlayers weight of players of unreadable team
     */
    public ObjectWeights {
        for (double weight : new double[] {ball, goal, flag, line, players, teammates, opponents, unknownPlayers}) {
            if (!(weight >= 0) || Double.isInfinite(weight)) {
                throw new IllegalArgumentException("object weights must be finite and not negative");
            }
        }
    }

    /**
     * The weights in the thesis' order.
     *
     * @param weights eight weights, ball first
     * @return the weights
     */
    public static ObjectWeights of(double... weights) {
        if (weights.length != NAMES.length) {
            throw new IllegalArgumentException("object weights need " + NAMES.length + " values, not " + weights.length);
        }
        return new ObjectWeights(weights[0], weights[1], weights[2], weights[3], weights[4], weights[5], weights[6], weights[7]);
    }

    /**
     * The weights in the thesis' order.
     *
     * @return a new array of eight, ball first
     */
    public double[] toArray() {
        return new double[] {ball, goal, flag, line, players, teammates, opponents, unknownPlayers};
    }

    /**
     * Reads the written form, positional or by name.
     *
     * @param text e.g. {@code 1/0/1/1/0/1/1/1} or {@code ball=1,goal=1}
     * @return the weights; a malformed text is an {@code IllegalArgumentException}
     */
    public static ObjectWeights parse(String text) {
        return of(Weights.parse(text, NAMES, "object weights"));
    }

    /**
     * The positional form, {@code 1/0/1/1/0/1/1/1}.
     *
     * @return the weights, slash-separated
     */
    public String format() {
        return Weights.format(toArray());
    }

    @Override
    public String toString() {
        return format();
    }
}
