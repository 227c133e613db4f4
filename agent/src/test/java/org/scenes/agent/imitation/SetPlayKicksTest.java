package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;

class SetPlayKicksTest {
    private static final Observer LEFT_TEN = new Observer("T", Side.LEFT, 10);

    private static Scene at(int cycle, String mode, Action action) {
        World world = new World(-0.3, 0, 0, 0, 0, 0, 8000, 1, 0, 0, 0, 0, 0, 0, List.of(), mode, 0, 0);
        return new Scene(cycle, LEFT_TEN, List.of(), List.of(action), null, 0, world);
    }

    /** A set play of the left team: the player turns for {@code wait} cycles, then kicks; play goes on. */
    private static List<Scene> setPlay(String mode, int start, int wait, Action kick, List<Scene> kicks) {
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < wait; t++) {
            scenes.add(at(start + t, mode, Action.turn(30)));
        }
        Scene kicked = at(start + wait, mode, kick);
        kicks.add(kicked);
        scenes.add(kicked);
        scenes.add(at(start + wait + 1, "play_on", Action.kick(100, 0))); // a kick in play is no set play's
        scenes.add(at(start + wait + 2, "play_on", Action.dash(100)));
        return scenes;
    }

    private static List<Scene> kickOff(int start, int wait, List<Scene> kicks) {
        return setPlay("kick_off_l", start, wait, Action.kick(50, 180), kicks);
    }

    @Test
    void theRecordedKickIsDueAfterTheMedianWaitOfItsKind() {
        List<Scene> kicks = new ArrayList<>();
        List<Scene> scenes = new ArrayList<>(kickOff(0, 20, kicks));
        scenes.addAll(kickOff(100, 30, kicks));
        scenes.addAll(kickOff(200, 40, kicks));
        SetPlayKicks recorded = SetPlayKicks.of(scenes);
        assertEquals(3, recorded.size());
        assertNull(recorded.due("kick_off_l", Side.LEFT, 29, 0, 0));
        assertSame(kicks.get(0), recorded.due("kick_off_l", Side.LEFT, 30, 0, 0));
        // the other team's kick-off, another kind, play on: none
        assertNull(recorded.due("kick_off_r", Side.LEFT, 100, 0, 0));
        assertNull(recorded.due("free_kick_l", Side.LEFT, 100, 0, 0));
        assertNull(recorded.due("play_on", Side.LEFT, 100, 0, 0));
        // a right player reads kick_off_r as its own
        assertEquals("kick_off", SetPlayKicks.ownKind("kick_off_r", Side.RIGHT));
        assertNull(SetPlayKicks.ownKind("goal_l", Side.LEFT));
    }

    @Test
    void aKickWhoseSceneHeardTheRefereesPlayOnStillEndedItsSetPlay() {
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < 25; t++) {
            scenes.add(at(t, "kick_off_l", Action.turn(30)));
        }
        // the kick's world model already heard play_on (HELIOS base's recorded kick-offs)
        Scene kick = at(25, "play_on", Action.kick(60, 0));
        scenes.add(kick);
        scenes.add(at(26, "play_on", Action.kick(100, 0)));
        SetPlayKicks recorded = SetPlayKicks.of(scenes);
        assertEquals(1, recorded.size());
        assertSame(kick, recorded.due("kick_off_l", Side.LEFT, 25, 0, 0));
        assertNull(recorded.due("kick_off_l", Side.LEFT, 24, 0, 0));
    }

    @Test
    void aKindThePlayerNeverTookIsTakenAsItsTeamTookIt() {
        List<Scene> own = new ArrayList<>();
        List<Scene> others = new ArrayList<>();
        SetPlayKicks player = SetPlayKicks.of(kickOff(0, 20, own));
        List<Scene> team = new ArrayList<>(kickOff(0, 50, others));
        team.addAll(setPlay("free_kick_l", 100, 15, Action.kick(80, 10), others));
        SetPlayKicks withTeam = player.orTeams(SetPlayKicks.of(team));
        // its own kick-off, after its own wait; the team's free kick, after the team's wait
        assertSame(own.get(0), withTeam.due("kick_off_l", Side.LEFT, 20, 0, 0));
        assertNull(withTeam.due("free_kick_l", Side.LEFT, 14, 0, 0));
        assertSame(others.get(1), withTeam.due("free_kick_l", Side.LEFT, 15, 0, 0));
        assertNull(player.due("free_kick_l", Side.LEFT, 1000, 0, 0), "alone it never takes a free kick");
        assertSame(player, player.orTeams(SetPlayKicks.of(kickOff(0, 5, new ArrayList<>()))),
                "nothing the team took that it did not");
    }

    @Test
    void filesOfOnePlayerMergeAndAPlayerThatNeverKickedHasNone() {
        List<Scene> kicks = new ArrayList<>();
        SetPlayKicks merged = SetPlayKicks.of(kickOff(0, 10, kicks)).with(SetPlayKicks.of(kickOff(0, 50, kicks)));
        assertEquals(2, merged.size());
        List<Scene> waiting = new ArrayList<>();
        for (int t = 0; t < 60; t++) {
            waiting.add(at(t, "kick_off_l", Action.turn(30)));
        }
        assertSame(SetPlayKicks.NONE, SetPlayKicks.of(waiting));
        assertNull(SetPlayKicks.NONE.due("kick_off_l", Side.LEFT, 1000, 0, 0));
    }

    /** A kick-in of the left team with the ball at ({@code x}, {@code y}), taken after 5 cycles. */
    private static List<Scene> kickIn(int start, double x, double y, Action kick, List<Scene> kicks) {
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t <= 5; t++) {
            World world = new World(x - 0.5, y, 0, 0, 0, 0, 8000, 1, 0, x, y, 0, 0, 0, List.of(), "kick_in_l", 0, 0);
            Scene scene = new Scene(start + t, LEFT_TEN, List.of(), List.of(t < 5 ? Action.turn(30) : kick), null, 0, world);
            scenes.add(scene);
            if (t == 5) {
                kicks.add(scene);
            }
        }
        scenes.add(at(start + 6, "play_on", Action.dash(100)));
        return scenes;
    }

    @Test
    void theKickTakenNearestWhereTheBallLiesIsTheOneTaken() {
        List<Scene> kicks = new ArrayList<>();
        List<Scene> scenes = new ArrayList<>(kickIn(0, 10, -34, Action.kick(60, 90), kicks));
        scenes.addAll(kickIn(100, 20, 34, Action.kick(60, -90), kicks));
        SetPlayKicks recorded = SetPlayKicks.of(scenes);
        // from the far touchline the kick towards the field is the one taken there
        assertSame(kicks.get(1), recorded.taken("kick_in_l", Side.LEFT, -5, 34));
        assertSame(kicks.get(0), recorded.taken("kick_in_l", Side.LEFT, 30, -34));
        assertSame(kicks.get(1), recorded.due("kick_in_l", Side.LEFT, 5, 25, 34));
        assertNull(recorded.due("kick_in_l", Side.LEFT, 4, 25, 34));
        assertSame(kicks.get(0), recorded.taken("kick_in_l", Side.LEFT, Double.NaN, Double.NaN), "no ball: the first");
        assertNull(recorded.taken("kick_in_r", Side.LEFT, 10, -34), "the other team's kick-in");
    }
}
