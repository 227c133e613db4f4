package org.scenes.simulator.teacher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class KrisletTest {
    private final List<String> sent = new ArrayList<>();
    private final Krislet krislet = new Krislet(new Random(1));

    private static final String SENSE_BODY = "(sense_body 0 (view_mode high normal) (stamina 8000 1) (speed 0 0)"
            + " (head_angle 0) (kick 0) (dash 0) (turn 0) (say 0) (turn_neck 0) (catch 0) (move 0) (change_view 0))";

    /** The command Krislet sends at its next think time (at most two steps) after this see, the step's see. */
    private String see(String see) {
        assertEquals(null, answer(SENSE_BODY));
        String command = answer(see);
        return command != null ? command : answer(SENSE_BODY);
    }

    private String answer(String message) {
        sent.clear();
        krislet.receive(message, sent::add);
        assertTrue(sent.size() <= 1, sent.toString());
        return sent.isEmpty() ? null : sent.get(0);
    }

    @Test
    void movesIntoItsOwnHalfOnceAfterTheParameters() {
        answer("(init l 3 before_kick_off)");
        String move = answer("(player_type (id 0)(player_speed_max 1.05))");
        assertTrue(move.matches("\\(move -\\d+\\.\\d+ -?\\d+\\.\\d+\\)"), move);
        assertEquals(null, answer("(player_type (id 1)(player_speed_max 1.05))"));
    }

    @Test
    void turnsWhenTheBallIsNotSeen() {
        assertEquals("(turn 40.0)", see("(see 12 ((f c) 10 3) ((g r) 50.1 -4))"));
    }

    @Test
    void turnsToAFarBallOffCentre() {
        assertEquals("(turn -17.0)", see("(see 12 ((b) 12.2 -17))"));
    }

    @Test
    void dashesTenTimesTheDistanceToAFarBallAhead() {
        assertEquals("(dash 122.0)", see("(see 12 ((b) 12.2 0 0.1 0))"));
    }

    @Test
    void kicksTowardsTheOpponentGoalWhenClose() {
        answer("(init r 3 before_kick_off)");
        assertEquals("(turn 40.0)", see("(see 12 ((b) 0.7 10) ((g r) 20 5))"));
        assertEquals("(kick 100.0 -31.0)", see("(see 12 ((b) 0.7 10) ((g l) 40.4 -31))"));
    }

    @Test
    void takesABallSeenBehindForTheBall() {
        answer("(init l 3 before_kick_off)");
        assertEquals("(turn 88.0)", see("(see 12 ((B) 1.6 88))"));
        assertEquals("(kick 100.0 -30.0)", see("(see 14 ((B) 0.6 -80) ((g r) 40 -30))"));
    }

    @Test
    void waitsForASeeTakenAfterItsLastCommand() {
        answer(SENSE_BODY);
        answer("(see 0 ((b) 12.2 -17))");
        assertEquals("(turn -17.0)", answer(SENSE_BODY));
        assertEquals(null, answer(SENSE_BODY));
        assertEquals(null, answer(SENSE_BODY), "its latest see is from before the turn");
        assertEquals("(dash 122.0)", answer("(see 3 ((b) 12.2 0))"), "decided on the step's see");
        assertEquals(null, answer(SENSE_BODY));
        assertEquals(null, answer(SENSE_BODY), "the see came in the step of the dash");
        assertEquals("(dash 122.0)", answer(SENSE_BODY), "no see came during the step: it acts on what it has");
    }

    @Test
    void answersOnlySees() {
        assertEquals(null, answer(SENSE_BODY));
        assertEquals(null, answer("(hear 0 referee kick_off_l)"));
    }

    @Test
    void thinksEverySecondStepFromTheLatestSee() {
        assertEquals(null, answer(SENSE_BODY), "nothing seen yet");
        answer("(see 0 ((b) 12.2 -17))");
        assertEquals("(turn -17.0)", answer(SENSE_BODY));
        answer("(see 1 ((b) 12.2 5))");
        assertEquals(null, answer(SENSE_BODY));
        answer("(see 2 ((b) 12.2 0))");
        assertEquals("(dash 122.0)", answer(SENSE_BODY));
    }
}
