package org.scenes.simulator.teacher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class StateBasedKrisletTest {
    private final List<String> sent = new ArrayList<>();
    private final StateBasedKrislet brain = new StateBasedKrislet(new Random(1));

    private String answer(String message) {
        sent.clear();
        brain.receive(message, sent::add);
        return sent.isEmpty() ? null : sent.get(0);
    }

    @Test
    void searchesTowardsWhereTheBallWasLastSeen() {
        answer("(see 1 ((b) 20 -30))");
        assertEquals("(turn -40.0)", answer("(see 2 ((f c) 10 3))"));
        assertEquals(StateBasedKrislet.State.SEARCH, brain.state);
        answer("(see 3 ((b) 20 25))");
        assertEquals("(turn 40.0)", answer("(see 4)"));
    }

    @Test
    void chasesWithToleranceAndGentleDashesNearTheBall() {
        assertEquals("(dash 100.0)", answer("(see 1 ((b) 20 8))"));
        assertEquals("(turn 12.0)", answer("(see 2 ((b) 20 12))"));
        assertEquals("(dash 60.0)", answer("(see 3 ((b) 3 0))"));
        assertEquals(StateBasedKrislet.State.CHASE, brain.state);
    }

    @Test
    void dribblesFarFromGoalAndShootsNearIt() {
        answer("(init l 4 before_kick_off)");
        assertEquals("(kick 40.0 5.0)", answer("(see 1 ((b) 0.6 3) ((g r) 45.2 5))"));
        assertEquals(StateBasedKrislet.State.DRIBBLE, brain.state);
        assertEquals("(kick 100.0 -12.0)", answer("(see 2 ((b) 0.6 3) ((g r) 20.1 -12))"));
        assertEquals(StateBasedKrislet.State.SHOOT, brain.state);
        assertEquals("(turn 40.0)", answer("(see 3 ((b) 0.6 3) ((g l) 20.1 -12))"));
    }

    @Test
    void placesItselfByUniformNumber() {
        answer("(init r 4 before_kick_off)");
        String move = answer("(player_type (id 0))");
        assertTrue(move.startsWith("(move -2"), move); // second row: x between -22 and -20
    }
}
