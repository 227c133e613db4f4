package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.simulator.Brain;

class PacedBrainTest {
    /** The steps at which a brain paced to {@code steps} decided, over {@code total} steps of a sense_body and a see each. */
    private static List<Integer> decisions(double steps, int total) {
        List<Integer> decided = new ArrayList<>();
        int[] step = {0};
        Brain inner = (message, send) -> {
            if (message.startsWith("(see ")) {
                decided.add(step[0]);
            }
        };
        Brain paced = PacedBrain.pace(inner, steps);
        for (step[0] = 1; step[0] <= total; step[0]++) {
            paced.receive("(sense_body " + step[0] + ")", command -> { });
            paced.receive("(see " + step[0] + ")", command -> { });
        }
        return decided;
    }

    private static List<Integer> gaps(List<Integer> decided) {
        List<Integer> gaps = new ArrayList<>();
        for (int i = 1; i < decided.size(); i++) {
            gaps.add(decided.get(i) - decided.get(i - 1));
        }
        return gaps;
    }

    @Test
    void wholeStepsDecideEveryNthStepExactly() {
        assertTrue(gaps(decisions(2, 1000)).stream().allMatch(gap -> gap == 2));
        assertTrue(gaps(decisions(3, 1000)).stream().allMatch(gap -> gap == 3));
        assertEquals(1000, decisions(0, 1000).size(), "not paced: every see");
    }

    @Test
    void aFractionDecidesNowAndThenAStepEarlyAtItsMeanRate() {
        List<Integer> decided = decisions(1.96, 1000);
        List<Integer> gaps = gaps(decided);
        assertTrue(gaps.stream().allMatch(gap -> gap == 1 || gap == 2), gaps.toString());
        long early = gaps.stream().filter(gap -> gap == 1).count();
        assertTrue(early > 10 && early < 40, "one-step gaps: " + early);
        // 1000 steps / 1.96 = 510 decisions; the whole-step pacing of 2 makes 500
        assertEquals(510, decided.size(), 2);
    }

    @Test
    void stepsBelowOneAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> PacedBrain.pace((message, send) -> { }, 0.5));
        assertThrows(IllegalArgumentException.class, () -> PacedBrain.pace((message, send) -> { }, -1));
        assertEquals("1.96", PacedBrain.text(1.96));
        assertEquals("2", PacedBrain.text(2));
    }
}
