package org.scenes.plugins.selectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.ActionWeights;
import org.scenes.api.Neighbour;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;

class SelectorsTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    private static List<Neighbour> neighbours(Action... actions) {
        List<Neighbour> list = new ArrayList<>();
        for (int i = 0; i < actions.length; i++) {
            List<Action> list1 = actions[i] == null ? List.of() : List.of(actions[i]);
            list.add(new Neighbour(new Scene(i, Observer.UNKNOWN, List.of(), list1), i, i));
        }
        return list;
    }

    private static ActionSelector selector(String name, Map<String, String> options, ActionWeights weights) {
        return REGISTRY.selector(name, PluginConfig.DEFAULT.withOptions(options).withActionWeights(weights));
    }

    @Test
    void aNeighbourWithoutActionIsChosenAsNoActionUnlessNoneWeighsNothing() {
        // an unanswered see kept by convert --unanswered keep: the teacher waited there
        List<Neighbour> nearest = neighbours(null, Action.dash(30), null, Action.turn(5));
        assertNull(selector("first-valid", Map.of(), ActionWeights.DEFAULT).select(nearest, new SplittableRandom(1)));
        assertNull(selector("vote", Map.of(), ActionWeights.DEFAULT).select(nearest, new SplittableRandom(1)),
                "none has two votes against one each");
        assertNull(selector("vote", Map.of("params", "average"), ActionWeights.DEFAULT)
                .select(nearest, new SplittableRandom(1)));
        assertEquals(Action.dash(30), selector("vote", Map.of(), ActionWeights.parse("none=0"))
                .select(nearest, new SplittableRandom(1)));
        assertEquals(Action.dash(30), selector("vote", Map.of("params", "average"), ActionWeights.parse("none=0.4"))
                .select(neighbours(null, Action.dash(30), Action.dash(30)), new SplittableRandom(1)));
        assertEquals(Action.dash(30), selector("first-valid", Map.of(), ActionWeights.parse("none=0"))
                .select(nearest, new SplittableRandom(1)));
    }

    @Test
    void firstValidSkipsMissingAndZeroWeightActions() {
        ActionSelector first = selector("first-valid", Map.of(), ActionWeights.parse("none=0,turn_neck=0"));
        assertEquals(Action.dash(30), first.select(neighbours(null, Action.turnNeck(10), Action.dash(30), Action.turn(5)),
                new SplittableRandom(1)));
        assertNull(first.select(neighbours(null, Action.turnNeck(10)), new SplittableRandom(1)));
    }

    @Test
    void voteCountsActionWeightsAndBreaksTiesByTheNearest() {
        List<Neighbour> nearest = neighbours(Action.turn(10), Action.dash(40), Action.kick(100, 0), Action.dash(60), Action.turn(20));
        assertEquals(Action.turn(10), selector("vote", Map.of(), ActionWeights.DEFAULT).select(nearest, new SplittableRandom(1)),
                "dash and turn tie at 2; turn holds the nearest");
        assertEquals(Action.kick(100, 0), selector("vote", Map.of(), ActionWeights.parse("kick=3"))
                .select(nearest, new SplittableRandom(1)));
        assertEquals(Action.dash(50), selector("vote", Map.of("params", "average"), ActionWeights.parse("dash=2"))
                .select(nearest, new SplittableRandom(1)));
    }

    @Test
    void randomAndVoteRandomRepeatWithTheSeed() {
        List<Neighbour> nearest = neighbours(Action.turn(10), Action.dash(40), Action.kick(100, 0), Action.dash(60));
        ActionSelector random = selector("random", Map.of(), ActionWeights.DEFAULT);
        Set<Action> seen = new HashSet<>();
        for (int seed = 0; seed < 40; seed++) {
            Action a = random.select(nearest, new SplittableRandom(seed));
            assertEquals(a, random.select(nearest, new SplittableRandom(seed)));
            seen.add(a);
        }
        assertEquals(4, seen.size(), "every neighbour gets picked");
        ActionSelector never = selector("vote-random", Map.of("percent", "0"), ActionWeights.DEFAULT);
        ActionSelector always = selector("vote-random", Map.of("percent", "100"), ActionWeights.DEFAULT);
        int notVote = 0;
        for (int seed = 0; seed < 40; seed++) {
            assertEquals(Action.dash(40), never.select(nearest, new SplittableRandom(seed)));
            if (!always.select(nearest, new SplittableRandom(seed)).equals(Action.dash(40))) {
                notVote++;
            }
        }
        assertTrue(notVote > 10, "always random: " + notVote);
        assertThrows(PluginException.class, () -> selector("vote-random", Map.of("percent", "120"), ActionWeights.DEFAULT));
        assertThrows(PluginException.class, () -> selector("vote", Map.of("params", "median"), ActionWeights.DEFAULT));
    }

    @Test
    void averageOnlyOverNeighboursOfTheChosenType() {
        List<Neighbour> nearest = neighbours(Action.kick(100, 10), Action.dash(40), Action.kick(50, -30));
        Action chosen = selector("first-valid", Map.of("params", "average"), ActionWeights.DEFAULT)
                .select(nearest, new SplittableRandom(1));
        assertEquals(ActionType.KICK, chosen.type());
        assertEquals(75, chosen.first(), 1e-12);
        assertEquals(-10, chosen.second(), 1e-12);
    }
}
