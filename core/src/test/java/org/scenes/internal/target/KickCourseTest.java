package org.scenes.internal.target;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Relation;
import org.scenes.api.World;

class KickCourseTest {
    /** A kicker at (x, 0) facing +x with the ball 0.5 m ahead, at rest, and these players. */
    private static World kicker(double x, World.Player... players) {
        return new World(x, 0, 0, 0, 0, 0, 8000, 1, 0, x + 0.5, 0, 0, 0, 0, List.of(players), "play_on", 0, 0);
    }

    /** Whether the kick does not lose the ball. */
    private static boolean keeps(Action kick, World own) {
        return KickCourse.outcome(kick, own) != KickCourse.Outcome.LOST;
    }

    private static World.Player opponent(double x, double y, int age) {
        return new World.Player(Relation.OPPONENT, 0, x, y, age);
    }

    private static World.Player teammate(double x, double y) {
        return new World.Player(Relation.TEAMMATE, 0, x, y, 0);
    }

    @Test
    void aPassToAnOpenTeammateKeepsTheBall() {
        World own = kicker(0, teammate(15, 0), opponent(15, 12, 0));
        assertTrue(keeps(Action.kick(60, 0), own));
    }

    @Test
    void aKickIntoAnOpponentsPathHandsItOver() {
        World own = kicker(0, teammate(25, 0), opponent(8, 3, 0));
        assertFalse(keeps(Action.kick(60, 0), own));
        // the same kick turned away from the opponent, towards the open teammate on the other side
        World other = kicker(0, teammate(14, -8), opponent(8, 3, 0));
        assertTrue(keeps(Action.kick(70, -30), other));
    }

    @Test
    void aPassToATeammateBeyondTheSecondLastOpponentDoesNotKeepIt() {
        // kicker at 20, the opponents' last two at 49 (the goalie) and 34; the teammate 12 m ahead at 32 is onside
        World onside = kicker(20, teammate(32, 0), opponent(49, 0, 0), opponent(34, 15, 0));
        assertTrue(keeps(Action.kick(60, 0), onside));
        World offside = kicker(20, teammate(32, 0), opponent(49, 0, 0), opponent(30, 15, 0));
        assertFalse(keeps(Action.kick(60, 0), offside));
        // with fewer than two opponents known there is no line to judge by
        assertTrue(keeps(Action.kick(60, 0), kicker(20, teammate(32, 0), opponent(49, 0, 0))));
    }

    @Test
    void aShotIntoTheOpenGoalKeepsItAndAKickOverTheLineDoesNot() {
        assertEquals(KickCourse.Outcome.SCORES, KickCourse.outcome(Action.kick(100, 0), kicker(40)));
        assertEquals(KickCourse.Outcome.LOST, KickCourse.outcome(Action.kick(100, 0), kicker(40, opponent(51, 0, 0))));
        assertFalse(keeps(Action.kick(100, 90), kicker(40)));
    }

    @Test
    void aBallThatWouldRollOutIsLostThoughATeammateCouldStopIt() {
        // the imitators' receivers rarely stop a ball: one that rolls on over the line is lost
        World own = new World(20, 20, 0, 0, 0, 0, 8000, 1, 0, 20.5, 20, 0, 0, 0, List.of(teammate(28, 28)),
                "play_on", 0, 0);
        assertFalse(keeps(Action.kick(100, 45), own));
        assertTrue(keeps(Action.kick(40, 45), own));
    }

    @Test
    void aShortDribbleKeepsTheBallForTheKickerUnlessAnOpponentStandsAtIt() {
        assertTrue(keeps(Action.kick(15, 0), kicker(0, opponent(6, 0, 0))));
        assertFalse(keeps(Action.kick(15, 0), kicker(0, opponent(1.8, 0.3, 0))));
    }

    @Test
    void opponentsRememberedTooLongAgoAndOtherActionsAreNotJudged() {
        World own = kicker(0, teammate(25, 0), opponent(8, 1, KickCourse.PLAYER_AGE + 1));
        assertTrue(keeps(Action.kick(60, 0), own));
        assertTrue(keeps(Action.dash(100), kicker(0, opponent(1, 0, 0))));
        World ballUnknown = new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, -1,
                List.of(opponent(1, 0, 0)), "play_on", 0, 0);
        assertTrue(keeps(Action.kick(60, 0), ballUnknown));
    }
}
