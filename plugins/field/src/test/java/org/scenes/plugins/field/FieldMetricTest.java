package org.scenes.plugins.field;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.Side;
import org.scenes.api.World;

class FieldMetricTest {
    private final SceneMetric metric = new FieldMetricProvider().create(PluginConfig.DEFAULT);

    private static Scene scene(Side side, double x, double y, double body, double ballX, double ballY, String mode) {
        World world = new World(x, y, body, 0, 0, 0, 8000, 1, 0, ballX, ballY, 0, 0, 0, List.of(), mode, 0, 0);
        return new Scene(1, new Observer("T", side, 2), List.of(), List.of(Action.dash(100)), null, 0, world);
    }

    @Test
    void theDistanceIsTheWeightedEuclideanOfTheFeatures() {
        Scene a = scene(Side.LEFT, 0, 0, 0, 5, 0, "play_on");
        // 10 m along x, ball at the same offset: position weight 0.1 per metre
        assertEquals(1, metric.distance(a, scene(Side.LEFT, 10, 0, 0, 15, 0, "play_on")), 1e-9);
        // the ball 3 m further away: ball weight 1 per metre
        assertEquals(3, metric.distance(a, scene(Side.LEFT, 0, 0, 0, 8, 0, "play_on")), 1e-9);
        // facing the other way: body weight 3 times a unit vector's change of 2
        assertEquals(6, metric.distance(a, scene(Side.LEFT, 0, 0, 180, 5, 0, "play_on")), 1e-9);
        assertEquals(0, metric.distance(a, a));
    }

    @Test
    void inTheBodysFrameABallAheadIsAheadWhicheverWayThePlayerFaces() {
        SceneMetric body = new FieldMetricProvider().create(PluginConfig.DEFAULT.withOptions(
                Map.of("ball-frame", "body", "body-weight", "0")));
        Scene east = scene(Side.LEFT, 0, 0, 0, 5, 0, "play_on");
        Scene south = scene(Side.LEFT, 0, 0, 90, 0, 5, "play_on");
        assertEquals(0, body.distance(east, south), 1e-9);
        SceneMetric field = new FieldMetricProvider().create(PluginConfig.DEFAULT.withOptions(Map.of("body-weight", "0")));
        assertEquals(Math.sqrt(50), field.distance(east, south), 1e-9);
    }

    @Test
    void playModesCompareFromThePlayersSide() {
        Scene leftKickOff = scene(Side.LEFT, 0, 0, 0, 5, 0, "kick_off_l");
        Scene rightKickOff = scene(Side.RIGHT, 0, 0, 0, 5, 0, "kick_off_r");
        Scene theirKickOff = scene(Side.RIGHT, 0, 0, 0, 5, 0, "kick_off_l");
        assertEquals(0, metric.distance(leftKickOff, rightKickOff));
        assertEquals(10, metric.distance(leftKickOff, theirKickOff), 1e-9);
        assertEquals("free_kick_opp", FieldMetricProvider.FieldMetric.ownMode("free_kick_r", Side.LEFT));
        assertEquals("play_on", FieldMetricProvider.FieldMetric.ownMode("play_on", Side.LEFT));
    }

    @Test
    void aModeWhereThePlayersPlaceThemselvesAddsThePlacementPenaltyAgainstPlay() {
        SceneMetric placing = new FieldMetricProvider().create(PluginConfig.DEFAULT.withOptions(
                Map.of("placement-penalty", "100")));
        Scene afterOurGoal = scene(Side.LEFT, -25, 0, 0, 0, 0, "goal_l");
        Scene afterTheirGoal = scene(Side.RIGHT, -25, 0, 0, 0, 0, "goal_l");
        Scene beforeKickOff = scene(Side.LEFT, -25, 0, 0, 0, 0, "before_kick_off");
        Scene play = scene(Side.LEFT, -25, 0, 0, 0, 0, "play_on");
        Scene goalKick = scene(Side.LEFT, -25, 0, 0, 0, 0, "goal_kick_l");
        // placement against play: both penalties
        assertEquals(Math.hypot(10, 100), placing.distance(afterOurGoal, play), 1e-9);
        assertEquals(Math.hypot(10, 100), placing.distance(beforeKickOff, goalKick), 1e-9);
        // two placement modes, or two modes of play, differ by the play mode's penalty alone
        assertEquals(10, placing.distance(afterOurGoal, afterTheirGoal), 1e-9);
        assertEquals(10, placing.distance(afterOurGoal, beforeKickOff), 1e-9);
        assertEquals(10, placing.distance(play, goalKick), 1e-9);
        // off by default
        assertEquals(10, metric.distance(afterOurGoal, play), 1e-9);
    }

    @Test
    void aSceneWithoutWorldIsMissingAwayAndOptionsAreChecked() {
        Scene without = new Scene(1, Observer.UNKNOWN, List.of(), List.of(Action.dash(100)));
        assertEquals(1000, metric.distance(scene(Side.LEFT, 0, 0, 0, 5, 0, "play_on"), without));
        SceneMetric cheap = new FieldMetricProvider().create(PluginConfig.DEFAULT.withOptions(Map.of("missing", "7")));
        assertEquals(7, cheap.distance(without, scene(Side.LEFT, 0, 0, 0, 5, 0, "play_on")));
        assertThrows(IllegalArgumentException.class,
                () -> new FieldMetricProvider().create(PluginConfig.DEFAULT.withOptions(Map.of("ball-weight", "-1"))));
        assertTrue(new FieldMetricProvider().options().containsKey("play-mode-penalty"));
    }

    @Test
    void aTeammateNearerTheBallInOneSceneOnlyAddsTheChaserPenalty() {
        Scene alone = scene(Side.LEFT, 0, 0, 0, 5, 0, "play_on");
        World w = alone.world();
        World withTeammate = new World(w.x(), w.y(), w.body(), 0, 0, 0, 8000, 1, 0, w.ballX(), w.ballY(), 0, 0, 0,
                List.of(new World.Player(Relation.TEAMMATE, 7, 6, 1, 0)), "play_on", 0, 0);
        World withOpponent = new World(w.x(), w.y(), w.body(), 0, 0, 0, 8000, 1, 0, w.ballX(), w.ballY(), 0, 0, 0,
                List.of(new World.Player(Relation.OPPONENT, 7, 6, 1, 0)), "play_on", 0, 0);
        Scene followed = new Scene(1, alone.observer(), List.of(), alone.actions(), null, 0, withTeammate);
        Scene marked = new Scene(1, alone.observer(), List.of(), alone.actions(), null, 0, withOpponent);
        assertEquals(10, metric.distance(alone, followed), 1e-9);
        assertEquals(0, metric.distance(alone, marked), 1e-9); // an opponent nearer the ball does not count
        SceneMetric cheap = new FieldMetricProvider().create(PluginConfig.DEFAULT.withOptions(
                Map.of("chaser-penalty", "2")));
        assertEquals(2, cheap.distance(alone, followed), 1e-9);
    }

    @Test
    void theNearestOpponentToTheBallCountsWhenWeightedUpToTenMetres() {
        Scene alone = scene(Side.LEFT, 0, 0, 0, 5, 0, "play_on");
        SceneMetric pressed = new FieldMetricProvider().create(PluginConfig.DEFAULT.withOptions(
                Map.of("opponent-weight", "0.5")));
        // opponents 2 m and 7 m from the ball (the nearer counts), one of unknown team ignored
        Scene marked = withPlayers(alone, new World.Player(Relation.OPPONENT, 7, 12, 0, 0),
                new World.Player(Relation.OPPONENT, 9, 5, 2, 0), new World.Player(Relation.UNKNOWN, 0, 5, 0.5, 0));
        assertEquals(0.5 * (10 - 2), pressed.distance(alone, marked), 1e-9, "none known counts as 10 m");
        Scene far = withPlayers(alone, new World.Player(Relation.OPPONENT, 9, 5, 25, 0));
        assertEquals(0, pressed.distance(alone, far), 1e-9, "25 m is as free as none");
        assertEquals(0, metric.distance(alone, marked), 1e-9, "weight 0 by default");
    }

    private static Scene withPlayers(Scene scene, World.Player... players) {
        World w = scene.world();
        World with = new World(w.x(), w.y(), w.body(), 0, 0, 0, 8000, 1, 0, w.ballX(), w.ballY(), 0, 0, 0,
                List.of(players), w.playMode(), 0, 0);
        return new Scene(scene.cycle(), scene.observer(), List.of(), scene.actions(), null, 0, with);
    }
}
