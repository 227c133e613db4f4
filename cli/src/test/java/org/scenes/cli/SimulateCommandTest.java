package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.files.Inputs;

/** Simulate a game, then convert its logs: the bundled pipeline with no recorded data. */
class SimulateCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    private int run(Object... args) {
        return cli.run(args);
    }

    private static byte[] text(Path log) throws IOException {
        try (var in = Inputs.open(log)) {
            return in.readAllBytes();
        }
    }

    @Test
    void simulateThenConvert() throws IOException {
        Path logs = dir.resolve("logs");
        assertEquals(0, run("simulate", "--teams", "krislet:2,krislet:3", "--cycles", "400", "--seed", "5",
                "--out-dir", logs), cli.err());
        String summary = cli.out();
        assertTrue(summary.matches("(?s)Score +Teal \\d+ : \\d+ Amber.*"), summary);
        assertTrue(summary.contains("5 player logs in"), summary);
        List<Path> written = List.of(logs.resolve("Teal_1.lsf.gz"), logs.resolve("Teal_2.lsf.gz"),
                logs.resolve("Amber_1.lsf.gz"), logs.resolve("Amber_2.lsf.gz"), logs.resolve("Amber_3.lsf.gz"));
        for (Path log : written) {
            assertTrue(Files.isRegularFile(log), log.toString());
        }
        assertEquals(0, run("convert", logs.resolve("Teal_1.lsf.gz"), logs.resolve("Amber_3.lsf.gz"),
                "--out-dir", dir.resolve("scenes")), cli.err());
        assertTrue(cli.out().contains("Malformed lines        0"), cli.out());
        assertTrue(Files.isRegularFile(dir.resolve("scenes/Teal_1.json.gz")));

        // same seed, same logs
        Path again = dir.resolve("again");
        assertEquals(0, run("simulate", "--teams", "krislet:2,krislet:3", "--cycles", "400", "--seed", "5",
                "--out-dir", again));
        for (Path log : written) {
            assertArrayEquals(text(log), text(again.resolve(log.getFileName())));
        }
    }

    @Test
    void badTeamsAreUsageErrors() {
        assertEquals(ExitCodes.USAGE, run("simulate", "--teams", "krislet:5", "--out-dir", dir));
        assertTrue(cli.err().contains("give two teams"), cli.err());
        assertEquals(ExitCodes.USAGE, run("simulate", "--teams", "nobody:5,krislet:5", "--out-dir", dir));
        assertTrue(cli.err().contains("available: krislet"), cli.err());
        assertEquals(ExitCodes.USAGE, run("simulate", "--teams", "krislet:12,krislet:5", "--out-dir", dir));
        assertEquals(ExitCodes.USAGE, run("simulate", "--names", "Same,Same", "--out-dir", dir));
        assertEquals(ExitCodes.USAGE, run("simulate", "--cycles", "0", "--out-dir", dir));
    }
}
