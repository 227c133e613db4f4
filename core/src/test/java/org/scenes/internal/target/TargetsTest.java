package org.scenes.internal.target;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.World;
import org.scenes.internal.validate.Validator;

class TargetsTest {
    private static final double DELTA = 1e-6;

    /** A standing player at (x, y) facing {@code body}, neck straight, the ball at (ballX, ballY) at rest. */
    static World world(double x, double y, double body, double ballX, double ballY) {
        return new World(x, y, body, 0, 0, 0, 8000, 1, 0, ballX, ballY, 0, 0, 0, List.of(), "play_on", 0, 0);
    }

    /** A scene of {@code world} whose see shows the ball where the world has it (none when {@code seesBall} is false). */
    static Scene scene(World world, boolean seesBall, Action... actions) {
        List<SeenObject> objects = List.of();
        if (seesBall) {
            double dx = world.ballX() - world.x();
            double dy = world.ballY() - world.y();
            double direction = Math.toDegrees(Math.atan2(dy, dx)) - world.body() - world.neck();
            objects = List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, Math.hypot(dx, dy),
                    org.scenes.internal.vision.VisionNumbers.normalize(direction), Grid.DEFAULT));
        }
        return new Scene(10, null, objects, List.of(actions), null, 0, world);
    }

    private static Action only(List<Action> actions) {
        assertEquals(1, actions.size(), actions.toString());
        return actions.get(0);
    }

    @Test
    void aTurnTowardsTheBallTurnsTowardsTheOwnBall() {
        // the recorded player turned 30 degrees to face its ball; this one has its ball 50 degrees to the left
        Scene chosen = scene(world(0, 0, 0, 10 * Math.cos(Math.toRadians(30)), 10 * Math.sin(Math.toRadians(30))), true,
                Action.turn(30));
        Scene query = scene(world(-20, 5, 90, -20 + 5 * Math.cos(Math.toRadians(40)), 5 + 5 * Math.sin(Math.toRadians(40))),
                true);
        Action turn = only(Targets.reach(chosen.actions(), chosen, query));
        assertEquals(ActionType.TURN, turn.type());
        assertEquals(-50, turn.first(), 1e-3);
    }

    @Test
    void aTurnWithoutTheBallInViewIsASearchAndKeepsItsMoment() {
        Scene chosen = scene(world(0, 0, 0, 10, 10), false, Action.turn(40));
        Scene query = scene(world(-20, 5, 90, 0, 0), true);
        assertEquals(Action.turn(40), only(Targets.reach(chosen.actions(), chosen, query)));
    }

    @Test
    void aTurnToAFieldDirectionFacesItFromTheOwnBodyWithTheOwnSpeed() {
        // the ball far off to the side: the turn faced the field direction 20 degrees
        Scene chosen = scene(world(0, 0, 0, 0, 30), true, Action.turn(20));
        World moving = new World(5, 5, -40, 0, 0.2, 0, 8000, 1, 0, 5, 35, 0, 0, 0, List.of(), "play_on", 0, 0);
        Action turn = only(Targets.reach(chosen.actions(), chosen, scene(moving, true)));
        // 60 degrees to turn, at 0.2 m/cycle the body turns moment / (1 + 5 * 0.2)
        assertEquals(120, turn.first(), 1e-6);
    }

    @Test
    void aDashIsSentAsRecordedWhenFacingItsWayAndTurnsFirstOtherwise() {
        Action dash = Action.dash(80);
        // the body 40 degrees off the goal and 130 off the ball: a field direction
        Scene chosen = scene(world(0, 0, 40, 0, -30), true, dash);
        double near = 40 + Targets.DASH_TOLERANCE - 1;
        assertEquals(dash, only(Targets.reach(chosen.actions(), chosen, scene(world(3, 3, near, 3, -27), true))));
        double far = 40 + Targets.DASH_TOLERANCE + 20;
        Action turn = only(Targets.reach(chosen.actions(), chosen, scene(world(3, 3, far, 3, -27), true)));
        assertEquals(-Targets.DASH_TOLERANCE - 20, turn.first(), 1e-9);
    }

    @Test
    void aKickAtTheGoalIsAimedAtTheGoalFromTheOwnBall() {
        // the recorded player kicked from (30, 10) straight at the goal's centre (52.5, 0)
        World donor = world(30, 10, 0, 30.5, 10);
        double atGoal = Math.toDegrees(Math.atan2(-10, 52.5 - 30.5));
        Scene chosen = scene(donor, true, Action.kick(100, atGoal));
        World own = world(40, -15, 90, 40, -14.5);
        Action kick = only(Targets.reach(chosen.actions(), chosen, scene(own, true)));
        assertEquals(ActionType.KICK, kick.type());
        double course = own.body() + kick.second();
        assertEquals(Math.toDegrees(Math.atan2(14.5, 52.5 - 40)), org.scenes.internal.vision.VisionNumbers.normalize(course),
                1e-6);
    }

    @Test
    void aPassKeepsItsFieldDirectionAndBallSpeed() {
        // a kick across the pitch (90 degrees off the goal): same field direction, power for the same speed
        World donor = world(0, 0, 0, 0.5, 0);
        Scene chosen = scene(donor, true, Action.kick(60, 90));
        World own = world(10, 10, -90, 10, 9.5); // the ball straight ahead of its body, as the recorded one's
        Action kick = only(Targets.reach(chosen.actions(), chosen, scene(own, true)));
        assertEquals(180, Math.abs(kick.second()), 1e-6);
        double donorRate = Targets.kickRate(donor);
        assertEquals(60 * donorRate, kick.first() * Targets.kickRate(own), 1e-9);
    }

    @Test
    void aNeckTurnLooksWhereTheRecordedHeadLookedAndStaysWithinTheNeck() {
        World donor = world(0, 0, 0, 0, 30);
        Scene chosen = scene(donor, false, Action.turnNeck(45));
        Action neck = only(Targets.reach(chosen.actions(), chosen, scene(world(0, 0, 30, 0, 30), false)));
        assertEquals(Action.turnNeck(15), neck);
        Action limited = only(Targets.reach(chosen.actions(), chosen, scene(world(0, 0, -90, 0, 30), false)));
        assertEquals(Action.turnNeck(90), limited);
    }

    @Test
    void aCatchIsAimedAtTheSeenBall() {
        Scene chosen = scene(world(-50, 0, 0, -49, 0), true, Action.catchBall(0));
        Action caught = only(Targets.reach(chosen.actions(), chosen, scene(world(-50, 0, 0, -49, 1), true)));
        assertEquals(45, caught.first(), 1e-6);
    }

    @Test
    void withoutAWorldModelTheRecordedActionsAreSent() {
        List<Action> recorded = List.of(Action.turn(30), Action.turnNeck(10));
        Scene chosen = new Scene(1, null, List.of(), recorded, null, 0, null);
        assertSame(recorded, Targets.reach(recorded, chosen, scene(world(0, 0, 0, 1, 1), true)));
        World lost = world(Double.NaN, Double.NaN, 0, 1, 1);
        assertSame(recorded, Targets.reach(recorded, scene(world(0, 0, 0, 1, 1), true, Action.turn(30)),
                scene(lost, true)));
    }

    @Test
    void aTurnAlreadyReachedGivesWayToTheNextNeighboursTarget() {
        Scene query = scene(world(0, 0, 0, 10, 0.2), true);
        // the nearest turned to face its ball, which this player already faces; the next dashed
        Scene turned = scene(world(0, 0, 0, 10 * Math.cos(Math.toRadians(20)), 10 * Math.sin(Math.toRadians(20))), true,
                Action.turn(20));
        Scene dashed = scene(world(0, 0, 0, 10, 0), true, Action.dash(100));
        List<Neighbour> nearest = List.of(new Neighbour(turned, 0, 0.1), new Neighbour(dashed, 1, 0.2));
        assertTrue(Targets.alreadyReached(Targets.reach(turned.actions(), turned, query), query));
        assertEquals(List.of(Action.dash(100)), Validator.prediction(Action.turn(20), nearest, query, Replay.TARGET));
        assertEquals(List.of(Action.turn(20)), Validator.prediction(Action.turn(20), nearest, query, Replay.RAW));
        assertFalse(Targets.alreadyReached(List.of(Action.dash(100)), query));
    }

    @Test
    void theInterceptionPointIsWhereTheRunFirstMeetsTheBallsCourse() {
        // the ball at rest 0.5 m away: reached where it lies
        assertArrayEquals(new double[] {0.5, 0}, Targets.intercept(world(0, 0, 0, 0.5, 0)), DELTA);
        // the ball 20 m ahead rolling away at 1.5 m a cycle: its course, decayed 0.94 a cycle, is
        // caught when the run (one turn, then a metre a cycle, plus the kicking reach) covers it
        World rolling = new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, 20, 0, 1.5, 0, 0, List.of(), "play_on", 0, 0);
        double[] point = Targets.intercept(rolling);
        double bx = 20;
        double v = 1.5;
        int caught = -1;
        for (int t = 0; t < 50 && caught < 0; t++) {
            if (bx <= Math.max(0, t - 1) * 1.0 + 1.085) {
                caught = t;
            } else {
                bx += v;
                v *= 0.94;
            }
        }
        assertTrue(caught > 0, "the run catches the ball within the horizon");
        assertArrayEquals(new double[] {bx, 0}, point, DELTA);
        assertTrue(point[0] > 35, "ahead of where the ball is now: " + point[0]);
        // no ball known: no point
        World blind = new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, 0, 0, 0, List.of(), "play_on",
                0, 0);
        assertNull(Targets.intercept(blind));
    }

    @Test
    void aRunTurnsFirstWhenThePointIsMoreThanTheRunToleranceOffTheBody() {
        World own = world(0, 0, 0, 30, 30);
        double[] ahead = {10 * Math.cos(Math.toRadians(10)), 10 * Math.sin(Math.toRadians(10))};
        double[] aside = {10 * Math.cos(Math.toRadians(30)), 10 * Math.sin(Math.toRadians(30))};
        assertEquals(Action.dash(80), Targets.goTo(ahead, own, 80, Action.turn(1)));
        Action turn = Targets.goTo(aside, own, 80, Action.turn(1));
        assertEquals(ActionType.TURN, turn.type());
        assertEquals(30, turn.first(), 1e-9); // standing still: the moment is the angle
        // within a metre: what the neighbour did there
        assertEquals(Action.turn(1), Targets.goTo(new double[] {0.5, 0.5}, own, 80, Action.turn(1)));
    }

    @Test
    void theTackleChanceFollowsTheServersModel() {
        // rcssserver: failure = (ahead / 2)^6 + (aside / 1.25)^6, nothing behind the body
        assertEquals(1 - Math.pow(0.5, 6), Targets.tackleChance(world(0, 0, 0, 1, 0)), DELTA);
        assertEquals(1 - Math.pow(0.75, 6) - Math.pow(0.4, 6), Targets.tackleChance(world(0, 0, 90, -0.5, 1.5)), DELTA);
        assertEquals(0, Targets.tackleChance(world(0, 0, 0, 2.5, 0)), DELTA);
        assertEquals(0, Targets.tackleChance(world(0, 0, 0, -0.5, 0)), DELTA, "behind the body");
    }

    @Test
    void aKickOrTackleThatCannotReachTheBallGivesWayToANeighbourThatCanOrToARunToTheBall() {
        Scene tackled = scene(world(0, 0, 0, 1, 0), true, Action.tackle(50));
        Scene dashed = scene(world(0, 0, 0, 3, 0), true, Action.dash(70));
        List<Neighbour> nearest = List.of(new Neighbour(tackled, 0, 0.1), new Neighbour(dashed, 1, 0.2));
        // the ball a metre ahead: the tackle stands; three metres ahead (the tackle area ends at 2 m): the dash
        Scene close = scene(world(5, 5, 0, 6, 5), true);
        assertEquals(List.of(Action.tackle(50)), Validator.prediction(Action.tackle(50), nearest, close, Replay.TARGET));
        Scene away = scene(world(5, 5, 0, 8, 5), true);
        assertTrue(Targets.futile(List.of(Action.tackle(50)), away));
        assertEquals(List.of(Action.dash(70)), Validator.prediction(Action.tackle(50), nearest, away, Replay.TARGET));
        // no neighbour does better: a run to the ball, turning to it first
        Scene kicked = scene(world(0, 0, 0, 0.8, 0), true, Action.kick(100, 0));
        Scene aside = scene(world(5, 5, 0, 5, 9), true);
        assertTrue(Targets.futile(List.of(Action.kick(100, 0)), aside), "the ball 4 m away");
        Action run = only(Validator.prediction(Action.kick(100, 0), List.of(new Neighbour(kicked, 0, 0)), aside,
                Replay.TARGET));
        assertEquals(ActionType.TURN, run.type());
        assertEquals(90, run.first(), 1e-6);
        // within reach, the kick is no longer futile
        assertFalse(Targets.futile(List.of(Action.kick(100, 0)), scene(world(5, 5, 0, 5.5, 5.3), true)));
    }

    @Test
    void aTurnBackAgainstThePreviousTurnGivesWayToANeighbourThatKeepsOn() {
        Scene turnBack = scene(world(0, 0, 0, 30, 30), false, Action.turn(-30));
        Scene dashOn = scene(world(0, 0, 0, 30, 30), false, Action.dash(100));
        List<Neighbour> nearest = List.of(new Neighbour(turnBack, 0, 0), new Neighbour(dashOn, 1, 1));
        Scene query = scene(world(5, 5, 0, 30, 30), false);
        Steering turnedRight = new Steering();
        turnedRight.sent(Action.turn(30));
        assertEquals(List.of(Action.dash(100)),
                Validator.prediction(Action.turn(-30), nearest, query, Replay.TARGET, null, turnedRight));
        // without a previous turn, or after a turn the same way, the turn stands
        assertEquals(List.of(Action.turn(-30)),
                Validator.prediction(Action.turn(-30), nearest, query, Replay.TARGET, null, new Steering()));
        Steering turnedLeft = new Steering();
        turnedLeft.sent(Action.turn(-20));
        assertEquals(List.of(Action.turn(-30)),
                Validator.prediction(Action.turn(-30), nearest, query, Replay.TARGET, null, turnedLeft));
        // a large turn back is a search: it stands
        Steering searched = new Steering();
        searched.sent(Action.turn(150));
        assertEquals(List.of(Action.turn(-30)),
                Validator.prediction(Action.turn(-30), nearest, query, Replay.TARGET, null, searched));
    }
}
