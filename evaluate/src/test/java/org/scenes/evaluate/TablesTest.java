package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.teacher.Teachers;

/** The JSON of {@code scenes evaluate --json}: the same bytes for the same games, run after run. */
class TablesTest {
    @Test
    void everyMapOfTheJsonKeepsItsKeysInTheirWrittenOrder() throws IOException {
        GameSetup.Team teacher = new GameSetup.Team("Teal", 1, Teachers.byName("krislet"));
        GameSetup.Team opponent = new GameSetup.Team("Amber", 1, Teachers.byName("krislet"));
        Evaluation.Plan plan = new Evaluation.Plan(teacher, Teachers.byName("krislet"), opponent, 200, List.of(1L));
        Map<String, Object> json = Tables.json(Comparison.of(Evaluation.run(plan, Arena.embedded(), done -> { })));

        Map<?, ?> figures = (Map<?, ?>) json.get("figures");
        assertFalse(figures.isEmpty());
        for (Object sides : figures.values()) {
            // Map.of's order is drawn once per JVM, so its key order alone would fail here only on some runs;
            // an insertion-ordered map is what makes every run write the same bytes
            assertInstanceOf(LinkedHashMap.class, sides);
            assertEquals(List.of("teacher", "imitator"), new ArrayList<>(((Map<?, ?>) sides).keySet()));
        }
        List<?> targets = (List<?>) json.get("targets");
        assertEquals(5, targets.size());
        for (Object target : targets) {
            assertInstanceOf(LinkedHashMap.class, target);
            assertEquals(List.of("target", "reached", "met"), new ArrayList<>(((Map<?, ?>) target).keySet()));
        }
        String text = new ObjectMapper().writeValueAsString(json);
        assertTrue(text.contains("\"agreement\":{\"teacher\":{\"mean\":null"), text);
        assertTrue(text.contains("\"targets\":[{\"target\":\""), text);
    }
}
