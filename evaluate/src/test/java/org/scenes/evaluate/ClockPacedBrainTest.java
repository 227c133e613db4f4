package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class ClockPacedBrainTest {
    private long now;
    private final List<String> decided = new ArrayList<>();
    private final List<String> passed = new ArrayList<>();
    private final ClockPacedBrain brain = new ClockPacedBrain((message, send) -> {
        if (message.startsWith("(see ")) {
            decided.add(now / 1_000_000 + ":" + message);
            send.accept("(turn 10)");
        } else {
            passed.add(message);
        }
    }, 200, () -> now);

    private List<String> at(long millis, String message) {
        now = millis * 1_000_000;
        List<String> sent = new ArrayList<>();
        brain.receive(message, sent::add);
        return sent;
    }

    @Test
    void afterEachDecisionItRestsThenDecidesOnTheFirstSeeTakenSince() {
        assertEquals(List.of("(turn 10)"), at(0, "(see 0 a)"), "the first see: at once");
        assertEquals(List.of(), at(100, "(sense_body 1)"));
        assertEquals(List.of(), at(150, "(see 1 b)"), "resting");
        assertEquals(List.of("(turn 10)"), at(210, "(sense_body 2)"), "rested, and a see came meanwhile");
        assertEquals(List.of(), at(300, "(see 3 c)"));
        assertEquals(List.of(), at(400, "(sense_body 4)"), "190 ms since the last decision");
        assertEquals(List.of("(turn 10)"), at(450, "(see 4 d)"), "rested: the fresh see itself");
        // no see after the decision at 450: it waits past its rest, then decides on what it has
        assertEquals(List.of(), at(660, "(sense_body 6)"));
        assertEquals(List.of("(turn 10)"), at(760, "(sense_body 7)"));
        assertEquals(List.of("0:(see 0 a)", "210:(see 1 b)", "450:(see 4 d)", "760:(see 4 d)"), decided);
        assertEquals(List.of("(sense_body 1)", "(sense_body 2)", "(sense_body 4)", "(sense_body 6)",
                "(sense_body 7)"), passed, "everything but sees reaches the brain as it comes");
    }

    @Test
    void aRestOfNothingIsNoPaceAndANegativeOneIsRefused() {
        org.scenes.simulator.BrainFactory factory = (team, random) -> (message, send) -> { };
        assertEquals(factory, ClockPacedBrain.pace(factory, 0));
        assertThrows(IllegalArgumentException.class, () -> ClockPacedBrain.pace(factory, -1));
    }
}
