package org.scenes.plugins.history;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionWeights;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;

class BodyVoteTest {
    private static Neighbour neighbour(int index, Action body) {
        return new Neighbour(Synthetic.scene(index, 0, 5, body, Action.turnNeck(index)), index, index);
    }

    @Test
    void noOpsVoteApartFromTurns() {
        ActionSelector vote = new BodyVoteSelectorProvider().create(PluginConfig.DEFAULT);
        List<Neighbour> nearest = List.of(neighbour(0, Action.turn(40)), neighbour(1, Action.dash(80)),
                neighbour(2, Action.turn(0)), neighbour(3, Action.dash(60)), neighbour(4, Action.turn(0)),
                neighbour(5, Action.turn(0)));
        // by type, turns would win 4 to 2; by body class the no-ops win 3 to 2 to 1
        assertEquals(Action.turn(0), vote.select(nearest, new SplittableRandom(1)));
        List<Neighbour> tie = List.of(neighbour(0, Action.turn(40)), neighbour(1, Action.dash(80)),
                neighbour(2, Action.dash(60)), neighbour(3, Action.turn(10)));
        assertEquals(Action.turn(40), vote.select(tie, new SplittableRandom(1)), "a tie goes to the nearer class");
    }

    @Test
    void actionWeightsCountAndZeroLeavesOut() {
        ActionSelector noDash = new BodyVoteSelectorProvider().create(PluginConfig.DEFAULT
                .withActionWeights(ActionWeights.parse("dash=0,turn=1")));
        List<Neighbour> nearest = List.of(neighbour(0, Action.dash(80)), neighbour(1, Action.dash(60)),
                neighbour(2, Action.turn(30)));
        assertEquals(Action.turn(30), noDash.select(nearest, new SplittableRandom(1)));
        assertNull(noDash.select(List.of(neighbour(0, Action.dash(80))), new SplittableRandom(1)));
    }

    @Test
    void scenesWithoutActionVoteForSendingNothing() {
        ActionSelector vote = new BodyVoteSelectorProvider().create(PluginConfig.DEFAULT);
        Neighbour unanswered1 = new Neighbour(new org.scenes.api.Scene(7, null, List.of(), List.of()), 7, 7);
        Neighbour unanswered2 = new Neighbour(new org.scenes.api.Scene(8, null, List.of(), List.of()), 8, 8);
        List<Neighbour> nearest = List.of(neighbour(0, Action.dash(80)), unanswered1, unanswered2);
        assertNull(vote.select(nearest, new SplittableRandom(1)), "two unanswered sees outvote one dash");
        ActionSelector noNone = new BodyVoteSelectorProvider().create(PluginConfig.DEFAULT
                .withActionWeights(ActionWeights.parse("none=0")));
        assertEquals(Action.dash(80), noNone.select(nearest, new SplittableRandom(1)));
    }
}
