package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** {@code scenes bench} on converted Krislet scenes prints one positive rate per metric. */
class BenchCommandTest {
    @TempDir
    Path dir;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        CommandLine commandLine = ScenesCommand.commandLine();
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        return commandLine.execute(args);
    }

    @Test
    void tableHasARatePerMetric() {
        Path log = Path.of(System.getProperty("scenes.shared"), "data", "krislet", "classic-game1", "Carleton_1.lsf.gz");
        Path scenes = dir.resolve("c1.json.gz");
        assertEquals(0, run("convert", "-o", scenes.toString(), log.toString()), err.toString());
        out.getBuffer().setLength(0);
        assertEquals(0, run("bench", "--time", "0.05", "--metric", "ball-goal", "--metric", "continuous", scenes.toString()), err.toString());
        List<String> rows = new ArrayList<>();
        for (String line : out.toString().split("\n")) {
            if (line.startsWith("ball-goal") || line.startsWith("continuous")) {
                rows.add(line);
                long rate = Long.parseLong(line.substring(line.lastIndexOf(' ') + 1).replace(",", ""));
                assertTrue(rate > 0, line);
            }
        }
        assertEquals(2, rows.size(), out.toString());
    }

    @Test
    void nonPositiveTimeIsAUsageError() {
        assertEquals(ExitCodes.USAGE, run("bench", "--time", "0", "x.json"));
    }
}
