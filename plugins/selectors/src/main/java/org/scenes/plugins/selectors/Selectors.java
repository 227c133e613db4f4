package org.scenes.plugins.selectors;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.random.RandomGenerator;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.ActionWeights;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.SelectorProvider;

/**
 * The built-in selectors. A neighbour is usable when it holds a primary action whose type has
 * a positive action weight, or holds no action (a see its player left unanswered, kept by
 * {@code convert --unanswered keep}) while {@code none} has a positive weight: choosing it is
 * choosing to send nothing, returned as null. Parameters come from the chosen neighbour ({@code params=copy}) or
 * are averaged over the usable neighbours of the chosen type ({@code params=average}).
 */
public final class Selectors {
    private Selectors() {
    }

    enum Params { COPY, AVERAGE }

    static Map<String, String> options(boolean random) {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("params", "copy (from the chosen neighbour; default) or average (over neighbours of the chosen type)");
        if (random) {
            options.put("percent", "share of decisions, in percent, taken from a random neighbour (default 10)");
        }
        return options;
    }

    static Params params(PluginConfig config) {
        return switch (config.option("params", "copy").toLowerCase(Locale.ROOT)) {
            case "copy" -> Params.COPY;
            case "average" -> Params.AVERAGE;
            default -> throw new PluginException("option params=" + config.option("params", "")
                    + " is unknown; use copy or average");
        };
    }

    static boolean usable(Neighbour neighbour, ActionWeights weights) {
        return weights.weight(neighbour.scene().actionType()) > 0;
    }

    static List<Neighbour> usable(List<Neighbour> nearest, ActionWeights weights) {
        List<Neighbour> usable = new ArrayList<>(nearest.size());
        for (Neighbour neighbour : nearest) {
            if (usable(neighbour, weights)) {
                usable.add(neighbour);
            }
        }
        return usable;
    }

    /** The action of {@code chosen}, its parameters averaged over same-type neighbours when asked. */
    static Action withParameters(Neighbour chosen, List<Neighbour> usable, Params params) {
        Action action = chosen.scene().primaryAction();
        if (params == Params.COPY || action == null) {
            return action;
        }
        double[] sum = new double[2];
        int[] count = new int[2];
        for (Neighbour neighbour : usable) {
            Action other = neighbour.scene().primaryAction();
            if (other == null || other.type() != action.type()) {
                continue;
            }
            for (int p = 0; p < 2; p++) {
                if (!Double.isNaN(other.parameter(p))) {
                    sum[p] += other.parameter(p);
                    count[p]++;
                }
            }
        }
        return new Action(action.type(), count[0] == 0 ? action.first() : sum[0] / count[0],
                count[1] == 0 ? action.second() : sum[1] / count[1]);
    }

    /** Weighted majority vote by type; ties go to the type of the nearest neighbour among them. */
    static Action vote(List<Neighbour> usable, ActionWeights weights, Params params) {
        if (usable.isEmpty()) {
            return null;
        }
        double[] score = new double[ActionType.values().length];
        for (Neighbour neighbour : usable) {
            ActionType type = neighbour.scene().actionType();
            score[type.ordinal()] += weights.weight(type);
        }
        Neighbour best = null;
        for (Neighbour neighbour : usable) { // nearest first, so the first of a tied type wins
            ActionType type = neighbour.scene().actionType();
            if (best == null || score[type.ordinal()] > score[best.scene().actionType().ordinal()]) {
                best = neighbour;
            }
        }
        return withParameters(best, usable, params);
    }

    /** Name, description and options shared by every selector provider here. */
    abstract static class Provider implements SelectorProvider {
        private final String name;
        private final String description;
        private final boolean takesPercent;

        Provider(String name, String description, boolean takesPercent) {
            this.name = name;
            this.description = description;
            this.takesPercent = takesPercent;
        }

        @Override
        public final String name() {
            return name;
        }

        @Override
        public final String description() {
            return description;
        }

        @Override
        public final Map<String, String> options() {
            return Selectors.options(takesPercent);
        }
    }

    public static final class FirstValid extends Provider {
        public FirstValid() {
            super("first-valid", "the nearest neighbour with a usable action", false);
        }

        @Override
        public ActionSelector create(PluginConfig config) {
            ActionWeights weights = config.actionWeights();
            Params params = params(config);
            return (nearest, random) -> {
                List<Neighbour> usable = usable(nearest, weights);
                return usable.isEmpty() ? null : withParameters(usable.get(0), usable, params);
            };
        }
    }

    public static final class Random extends Provider {
        public Random() {
            super("random", "a neighbour with a usable action, chosen at random", false);
        }

        @Override
        public ActionSelector create(PluginConfig config) {
            ActionWeights weights = config.actionWeights();
            Params params = params(config);
            return (nearest, random) -> pickRandom(usable(nearest, weights), random, params);
        }
    }

    static Action pickRandom(List<Neighbour> usable, RandomGenerator random, Params params) {
        return usable.isEmpty() ? null : withParameters(usable.get(random.nextInt(usable.size())), usable, params);
    }

    public static final class Vote extends Provider {
        public Vote() {
            super("vote", "majority vote by action type, each neighbour counting its type's action weight", false);
        }

        @Override
        public ActionSelector create(PluginConfig config) {
            ActionWeights weights = config.actionWeights();
            Params params = params(config);
            return (nearest, random) -> vote(usable(nearest, weights), weights, params);
        }
    }

    public static final class VoteRandom extends Provider {
        public VoteRandom() {
            super("vote-random", "vote, except a random neighbour for a given percentage of decisions", true);
        }

        @Override
        public ActionSelector create(PluginConfig config) {
            ActionWeights weights = config.actionWeights();
            Params params = params(config);
            double percent = config.doubleOption("percent", 10);
            if (!(percent >= 0 && percent <= 100)) {
                throw new PluginException("option percent=" + percent + " must lie between 0 and 100");
            }
            return (nearest, random) -> {
                List<Neighbour> usable = usable(nearest, weights);
                // always draw, so the random stream does not depend on the outcome
                boolean randomPick = random.nextDouble() * 100 < percent;
                return randomPick ? pickRandom(usable, random, params) : vote(usable, weights, params);
            };
        }
    }
}
