package org.scenes.plugins.history;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.random.RandomGenerator;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.ActionWeights;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.SelectorProvider;

/**
 * {@code body-vote}: the neighbours vote by body class (as {@code validate} scores it: a
 * {@code (turn 0)} is a no-op, not a turn), each counting its body action's action weight; the
 * class with most votes wins (ties: the one of the nearer neighbour), and its nearest member's
 * body action is taken. The plain {@code vote} counts by type, which puts no-ops among the turns.
 */
public final class BodyVoteSelectorProvider implements SelectorProvider {
    @Override
    public String name() {
        return "body-vote";
    }

    @Override
    public String description() {
        return "majority vote by body class (no-op apart from turn), the nearest action of the winning class";
    }

    @Override
    public ActionSelector create(PluginConfig config) {
        return new BodyVote(config.actionWeights());
    }

    static final class BodyVote implements ActionSelector {
        private final ActionWeights weights;

        BodyVote(ActionWeights weights) {
            this.weights = weights;
        }

        @Override
        public Action select(List<Neighbour> nearest, RandomGenerator random) {
            Map<String, Double> votes = new HashMap<>();
            Map<String, Action> first = new HashMap<>();
            for (Neighbour neighbour : nearest) {
                Action body = ActionLabel.bodyAction(neighbour.scene().actions());
                // a scene without any action (an unanswered see, kept by convert) votes for sending nothing
                double weight = body != null ? weights.weight(body.type())
                        : neighbour.scene().actions().isEmpty() ? weights.weight(ActionType.NONE) : 0;
                if (weight <= 0) {
                    continue;
                }
                String label = ActionLabel.BODY.of(neighbour.scene().actions());
                votes.merge(label, weight, Double::sum);
                first.putIfAbsent(label, body);
            }
            String best = null;
            for (Neighbour neighbour : nearest) { // nearest first, so a tie goes to the nearer class
                String label = ActionLabel.BODY.of(neighbour.scene().actions());
                Double count = votes.get(label);
                if (count != null && (best == null || count > votes.get(best))) {
                    best = label;
                }
            }
            return best == null ? null : first.get(best);
        }
    }
}
