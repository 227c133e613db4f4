package org.scenes.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.internal.convert.DropReason;

/** The convert job's totals, reduced in whatever order Spark merges the games' summaries. */
class ConvertSummaryTest {
    static GameConversion.LogResult log(String name, long scenes, String error, String... warnings) {
        EnumMap<DropReason, Long> dropped = new EnumMap<>(DropReason.class);
        dropped.put(DropReason.NO_ACTION, 2L);
        return new GameConversion.LogResult(name, error == null ? name + ".json.gz" : null, error, 10, 100, 5, scenes, 1,
                dropped, 3, new ArrayList<>(List.of(warnings)));
    }

    @Test
    void sumsTheGamesAndKeepsTheirLinesInGameOrderWhateverTheMergeOrder() {
        ConvertSummary first = ConvertSummary.of(0, List.of(log("a", 4, null, "a: line 3"), log("b", 0, "b: no scenes")));
        ConvertSummary second = ConvertSummary.of(1, List.of(log("c", 7, null, "c: line 1", "c: line 9")));
        ConvertSummary third = ConvertSummary.of(2, List.of(log("d", 1, null)));
        for (ConvertSummary total : List.of(ConvertSummary.merge(ConvertSummary.merge(first, second), third),
                ConvertSummary.merge(third, ConvertSummary.merge(second, first)))) {
            assertEquals(4, total.logs);
            assertEquals(12, total.scenes);
            assertEquals(40, total.lines);
            assertEquals(8, total.dropped(DropReason.NO_ACTION));
            assertEquals(12, total.malformed);
            assertEquals(3, total.written);
            assertEquals(List.of("a: line 3", "c: line 1", "c: line 9"),
                    total.warnings.stream().map(ConvertSummary.Line::text).toList());
            assertEquals(List.of("b: no scenes"), total.failures.stream().map(ConvertSummary.Line::text).toList());
            assertEquals(1, total.failureCount);
        }
    }

    @Test
    void keepsTheFirstLinesAndCountsTheRest() {
        List<GameConversion.LogResult> logs = new ArrayList<>();
        for (int i = 0; i < ConvertSummary.LINES_KEPT + 5; i++) {
            logs.add(log("log" + i, 1, null, "warning " + i));
        }
        ConvertSummary later = ConvertSummary.of(1, logs);
        ConvertSummary earlier = ConvertSummary.of(0, List.of(log("x", 1, null, "first")));
        ConvertSummary total = ConvertSummary.merge(later, earlier);
        assertEquals(ConvertSummary.LINES_KEPT, total.warnings.size());
        assertEquals(ConvertSummary.LINES_KEPT + 6, total.warningCount);
        assertEquals("first", total.warnings.get(0).text());
        assertEquals("warning " + (ConvertSummary.LINES_KEPT - 2), total.warnings.get(ConvertSummary.LINES_KEPT - 1).text());
    }
}
