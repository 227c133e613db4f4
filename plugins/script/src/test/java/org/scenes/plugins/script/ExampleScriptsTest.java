package org.scenes.plugins.script;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionWeights;
import org.scenes.api.EncodedMetric;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

/** The two scripts shipped in examples/scripts load through the registry and do what they say. */
class ExampleScriptsTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();
    private static final Path EXAMPLES = Path.of(System.getProperty("scenes.examples", "../../examples/scripts"));

    private static String example(String name) {
        Path file = EXAMPLES.resolve(name);
        assertTrue(Files.isRegularFile(file), file + " is missing");
        return "script:" + file;
    }

    private static SceneMetric ballGoal(String weights) {
        return REGISTRY.metric(example("ball-goal.groovy"),
                PluginConfig.DEFAULT.withObjectWeights(ObjectWeights.parse(weights)));
    }

    @Test
    void ballGoalComparesBallAndGoalCellsAndAngles() {
        SceneMetric metric = ballGoal("ball=1,goal=1");
        assertTrue(metric instanceof EncodedMetric<?>, "the example uses the fast form");
        assertTrue(metric.isTrueMetric());
        Scene query = Fixtures.scene(1, null, Fixtures.ball(3, 0), Fixtures.opponentGoal(30, 20));
        assertEquals(0, metric.distance(query, query));
        // Ball one row nearer (3 m -> 0.5 m), same direction: a row costs 3.
        Scene nearer = Fixtures.scene(2, null, Fixtures.ball(0.5, 0), Fixtures.opponentGoal(30, 20));
        assertEquals(3, metric.distance(query, nearer), 1e-12);
        // Ball one column to the right (0 -> 18 degrees): one column plus 18 x 0.05.
        Scene right = Fixtures.scene(3, null, Fixtures.ball(3, 18), Fixtures.opponentGoal(30, 20));
        assertEquals(1.9, metric.distance(query, right), 1e-12);
        // Same column, 10 degrees apart: only the angle counts.
        Scene turned = Fixtures.scene(4, null, Fixtures.ball(3, 0), Fixtures.opponentGoal(30, 10));
        assertEquals(0.5, metric.distance(query, turned), 1e-12);
        // Flags do not count; a missing goal costs 10.
        Scene noGoal = Fixtures.scene(5, null, Fixtures.ball(3, 0), Fixtures.flag(10, 5));
        assertEquals(10, metric.distance(query, noGoal), 1e-12);
        assertEquals(0, metric.distance(Fixtures.scene(6, null), Fixtures.scene(7, null, Fixtures.flag(3, 3))));
        // A part costs at most 20: ball far left and near versus far right and far.
        Scene opposite = Fixtures.scene(8, null, Fixtures.ball(0.5, -170), Fixtures.opponentGoal(30, 20));
        Scene other = Fixtures.scene(9, null, Fixtures.ball(40, 170), Fixtures.opponentGoal(30, 20));
        assertEquals(20, metric.distance(opposite, other), 1e-12);
    }

    @Test
    void ballGoalFollowsObjectWeights() {
        Scene query = Fixtures.scene(1, null, Fixtures.ball(3, 0), Fixtures.opponentGoal(30, 20));
        Scene other = Fixtures.scene(2, null, Fixtures.ball(0.5, 0));
        assertEquals(3 + 10, ballGoal("ball=1,goal=1").distance(query, other), 1e-12);
        assertEquals(3 * 3, ballGoal("ball=3").distance(query, other), 1e-12);
        assertEquals(0.5 * 10, ballGoal("goal=0.5").distance(query, other), 1e-12);
    }

    private static ActionSelector vote(String actionWeights) {
        return REGISTRY.selector(example("vote.groovy"),
                PluginConfig.DEFAULT.withActionWeights(ActionWeights.parse(actionWeights)));
    }

    private static Neighbour neighbour(int index, Action action) {
        return new Neighbour(Fixtures.scene(index, action), index, index);
    }

    @Test
    void voteTakesTheMostVotedTypeFromItsNearestScene() {
        Action dash = Action.dash(100);
        Action kick = Action.kick(80, -10);
        Action farKick = Action.kick(20, 30);
        List<Neighbour> nearest = List.of(neighbour(0, dash), neighbour(1, kick), neighbour(2, farKick));
        SplittableRandom random = new SplittableRandom(1);
        assertSame(kick, vote("1/1/1/1/1/1/1").select(nearest, random));
        // Dash weighing 3 outvotes two kicks.
        assertSame(dash, vote("dash=3,kick=1").select(nearest, random));
        // A tie goes to the type whose voter is nearest.
        assertSame(dash, vote("dash=2,kick=1").select(nearest, random));
    }

    @Test
    void voteWithoutActionsChoosesNothing() {
        List<Neighbour> nearest = List.of(neighbour(0, null), neighbour(1, null));
        assertNull(vote("1/1/1/1/1/1/1").select(nearest, new SplittableRandom(1)));
    }
}
