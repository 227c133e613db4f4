package org.scenes.internal.target;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Relation;
import org.scenes.api.World;

class KickFollowerTest {
    private static final List<Action> TURN_AWAY = List.of(Action.turn(90), Action.turnNeck(20));

    /** A player at the origin facing along x; its ball {@code ballX} m ahead rolling on at 0.6 m a cycle. */
    private static World world(double ballX, String mode, List<World.Player> players) {
        return new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, ballX, 0, 0.6, 0, 0, players, mode, 0, 0);
    }

    private static World world(double ballX) {
        return world(ballX, "play_on", List.of());
    }

    /** A follower whose player kicked in play on at cycle 100. */
    private static KickFollower kickedAt100() {
        KickFollower follower = new KickFollower();
        follower.sent(List.of(Action.kick(40, 0)), world(0.5), 100);
        return follower;
    }

    @Test
    void afterItsKickThePlayerRunsAfterTheBallKeepingItsGaze() {
        KickFollower follower = kickedAt100();
        List<Action> followed = follower.follow(TURN_AWAY, world(3), 101, 100);
        assertEquals(List.of(Action.dash(100), Action.turnNeck(20)), followed);
        assertEquals(1, follower.follows());
        List<Action> steered = follower.follow(TURN_AWAY, new World(0, 0, 0, 0, 0, 0, 8000, 1, 0, 0, 3, 0, 0.6, 0,
                List.of(), "play_on", 0, 0), 102, 100);
        assertEquals(ActionType.TURN, steered.get(0).type(), "a ball to the side: a turn towards its course first");
        assertEquals(90, steered.get(0).first(), 1, "it rolls along y, met about 6 m on");
        // an opponent ahead on the course would meet the ball after 5 cycles, the player after 7: a near race is run
        World.Player opponentAhead = new World.Player(Relation.OPPONENT, 6, 9.5, 0, 0);
        assertEquals(Action.dash(100), follower.follow(TURN_AWAY, world(3, "play_on", List.of(opponentAhead)), 103, 100).get(0));
        assertEquals(3, follower.follows());
    }

    @Test
    void theFollowEndsAfterItsCyclesAndNeedsAKickInPlayOn() {
        KickFollower follower = kickedAt100();
        assertSame(TURN_AWAY, follower.follow(TURN_AWAY, world(3), 100 + KickFollower.FOLLOW + 1, 100));
        assertSame(TURN_AWAY, new KickFollower().follow(TURN_AWAY, world(3), 101, 100), "no kick yet");
        KickFollower setPlay = new KickFollower();
        setPlay.sent(List.of(Action.kick(40, 0)), world(0.5, "free_kick_l", List.of()), 100);
        assertSame(TURN_AWAY, setPlay.follow(TURN_AWAY, world(3), 101, 100), "a set play's kicker may not touch it again");
        KickFollower dashed = new KickFollower();
        dashed.sent(List.of(Action.dash(100)), world(0.5), 100);
        assertSame(TURN_AWAY, dashed.follow(TURN_AWAY, world(3), 101, 100));
        assertEquals(0, follower.follows() + setPlay.follows() + dashed.follows());
    }

    @Test
    void noFollowWhenSomeoneIsFasterTheBallIsAtItsFeetOrAKickIsChosen() {
        KickFollower follower = kickedAt100();
        World.Player opponentAtTheBall = new World.Player(Relation.OPPONENT, 5, 4, 0, 0);
        World.Player teammateAhead = new World.Player(Relation.TEAMMATE, 9, 5, 0, 0);
        assertSame(TURN_AWAY, follower.follow(TURN_AWAY, world(3, "play_on", List.of(opponentAtTheBall)), 101, 100));
        assertSame(TURN_AWAY, follower.follow(TURN_AWAY, world(3, "play_on", List.of(teammateAhead)), 101, 100));
        assertSame(TURN_AWAY, follower.follow(TURN_AWAY, world(0.8), 101, 100), "within kicking reach");
        List<Action> kick = List.of(Action.kick(30, 10));
        assertSame(kick, follower.follow(kick, world(3), 101, 100));
        assertSame(TURN_AWAY, follower.follow(TURN_AWAY, world(3, "kick_in_r", List.of()), 101, 100));
        assertSame(TURN_AWAY, follower.follow(TURN_AWAY, world(40), 101, 100), "a long ball it cannot reach within the follow");
        assertEquals(0, follower.follows());
    }
}
