package org.scenes.app.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.app.TestFiles;

class ExportTest {
    @TempDir
    Path dir;

    @Test
    void everySceneIsARowOfTheColumnsInOrder() throws Exception {
        Path file = TestFiles.krislet(dir.resolve("a.json"), 1, 30);
        Export export = new Export(new Export.Request(List.of(file), Export.Format.csv, 1, Export.Label.primary, false, true,
                true, "NA"), null);
        assertEquals(List.of("cycle", "ball_dist", "ball_dir", "own_goal_dist", "own_goal_dir", "opp_goal_dist",
                "opp_goal_dir", "mate1_dist", "mate1_dir", "opp1_dist", "opp1_dir", "unknown_players", "previous_action",
                "previous_turn_moment", "turn_moment", "dash_power", "dash_dir", "kick_power", "kick_dir", "action"),
                export.columns());
        StringWriter out = new StringWriter();
        assertEquals(30, export.write(out));
        List<String> lines = out.toString().lines().toList();
        assertEquals(31, lines.size());
        assertEquals(String.join(",", export.columns()), lines.get(0));
        assertTrue(lines.get(1).startsWith("0,") && lines.get(1).contains(",NA,NA,") && lines.get(1).contains(",none,NA,"),
                lines.get(1));
    }

    @Test
    void keyScenesAloneAreRowsWithTheirInfluence() throws Exception {
        Path file = TestFiles.krislet(dir.resolve("a.json"), 2, 20);
        Export export = new Export(new Export.Request(List.of(file), Export.Format.arff, 0, Export.Label.primary, false, false,
                false, ""), path -> Map.of(3, 7, 11, 2));
        StringWriter out = new StringWriter();
        assertEquals(2, export.write(out));
        assertTrue(out.toString().contains("@attribute influence numeric\n"), out.toString());
        List<String> data = out.toString().lines().dropWhile(line -> !line.equals("@data")).skip(1).toList();
        assertEquals(2, data.size());
        assertTrue(data.get(0).startsWith("3,") && data.get(0).contains(",7,"), data.get(0));
    }
}
