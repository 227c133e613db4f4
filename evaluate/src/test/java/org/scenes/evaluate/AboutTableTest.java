package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The report's table of what was evaluated: values left-aligned, file lists wrapping between paths. */
class AboutTableTest {
    @Test
    void pathsBreakOnlyAfterASlashAndValuesAreLeftAligned() {
        Map<String, String> about = new LinkedHashMap<>();
        about.put("imitator learnt from", "2 scene files (900 scenes): scenes/sim-1/Teal_1.json.gz /tmp/a-b/Teal_2.json.gz");
        about.put("teacher games", "2 in logs (001-Teal_1-vs-Amber_0.rcg, 002-Teal_0-vs-Amber_0.rcg)");
        String html = HtmlReport.aboutTable(about);
        assertTrue(html.startsWith("<table class=\"about\">"), html);
        assertTrue(html.contains("(900 scenes): <span class=\"path\">scenes/</span><wbr><span class=\"path\">sim-1/</span><wbr>"
                + "<span class=\"path\">Teal_1.json.gz</span> <span class=\"path\">/</span><wbr>"), html);
        // a file name alone is one unbreakable piece, not broken at its dashes
        assertTrue(html.contains("<span class=\"path\">(001-Teal_1-vs-Amber_0.rcg,</span>"), html);
        assertTrue(html.contains("<tr><th>teacher games</th><td>2 in logs "), html);
    }
}
