package org.scenes.api;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class WeightsTest {
    @Test
    void objectWeightsParsePositionally() {
        ObjectWeights weights = ObjectWeights.parse("1/0/1/1/0/1/1/0.5");
        assertEquals(ObjectWeights.of(1, 0, 1, 1, 0, 1, 1, 0.5), weights);
        assertEquals(weights, ObjectWeights.parse("{1,0,1,1,0,1,1,0.5}"));
        assertEquals("1/0/1/1/0/1/1/0.5", weights.format());
    }

    @Test
    void namedObjectWeightsLeaveOtherClassesAtZero() {
        assertEquals(ObjectWeights.of(1, 2, 0, 0, 0, 0, 0, 0), ObjectWeights.parse("ball=1,goal=2"));
    }

    @Test
    void badObjectWeightsSayWhatIsWrong() {
        assertMessage("need 8 values", () -> ObjectWeights.parse("1/0/1"));
        assertMessage("unknown class 'balls'", () -> ObjectWeights.parse("balls=1"));
        assertMessage("'x' is not a number", () -> ObjectWeights.parse("1/0/1/1/0/1/1/x"));
        assertMessage("must be a finite number", () -> ObjectWeights.parse("ball=-1"));
    }

    @Test
    void actionWeightsDefaultToOneAndAcceptTheThesisSevenValues() {
        ActionWeights weights = ActionWeights.parse("0/1/2/0/1/1/1");
        assertEquals(2, weights.weight(ActionType.KICK));
        assertEquals(0, weights.weight(ActionType.TURN_NECK));
        assertEquals(1, weights.weight(ActionType.TACKLE), "tackle keeps 1 when not given");
        ActionWeights named = ActionWeights.parse("kick=3");
        assertEquals(3, named.weight(ActionType.KICK));
        assertEquals(1, named.weight(ActionType.DASH));
    }

    private static void assertMessage(String fragment, org.junit.jupiter.api.function.Executable call) {
        IllegalArgumentException error = assertThrows(IllegalArgumentException.class, call);
        assertTrue(error.getMessage().contains(fragment), error.getMessage());
    }
}
