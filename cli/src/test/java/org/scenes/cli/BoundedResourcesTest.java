package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 31.4: options that size work are bounded before anything is allocated or started (exit 2). */
class BoundedResourcesTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    @Test
    void threadCountsOutsideOneTo256AreUsageErrors() throws Exception {
        Path log = Files.writeString(dir.resolve("x.lsf"), "(init l 1 before_kick_off)\n(see 0 ((b) 1 2))\n(dash 100)\n");
        for (String threads : new String[] {"0", "-3", "1000000000"}) {
            assertEquals(ExitCodes.USAGE, cli.run("convert", log, "--threads", threads, "-o", dir.resolve("x.json")), threads);
            assertTrue(cli.err().contains("--threads must be from 1 to 256, not " + threads), cli.err());
            assertEquals(ExitCodes.USAGE, cli.run("experiment", dir.resolve("absent.groovy"), "--threads", threads,
                    "--out-dir", dir.resolve("r")), threads);
            assertTrue(cli.err().contains("--threads must be from 1 to 256"), cli.err());
        }
        assertEquals(ExitCodes.OK, cli.run("convert", log, "--threads", "256", "-o", dir.resolve("x.json")), cli.err());
    }

    @Test
    void aSyntheticKnowledgeBaseLargerThanTheHeapIsRefusedBeforeItIsMade() {
        assertEquals(ExitCodes.USAGE, cli.run("bench", "--synthetic", "2000000000", "--metric", "ball-goal"));
        assertTrue(cli.err().contains("--synthetic 2000000000 needs about") && cli.err().contains("MB of heap"), cli.err());
        assertEquals("", cli.out());
    }

    @Test
    void runningOutOfMemoryIsOneLineNamingTheHeapOption() {
        String message = Limits.outOfMemoryMessage();
        assertTrue(message.startsWith("out of memory (Java heap of ") && message.contains("SCENES_OPTS=-Xmx"), message);
        assertEquals(null, Limits.outOfMemory(new RuntimeException("x")));
        OutOfMemoryError error = new OutOfMemoryError("Java heap space");
        assertEquals(error, Limits.outOfMemory(new RuntimeException(new java.util.concurrent.ExecutionException(error))));
    }

    /** All-zero object weights crashed the packed greedy scan ("Index 0 out of bounds"): every scene is then as near. */
    @Test
    void allZeroObjectWeightsMatchEveryStoredSceneAsNear() throws Exception {
        Path train = Files.writeString(dir.resolve("t.lsf"), "(init l 1 before_kick_off)\n"
                + "(see 0 ((b) 1 2) ((g r) 30 0))\n(dash 100)\n(see 1 ((b) 0.5 2) ((g r) 30 0))\n(kick 100 0)\n"
                + "(see 2 ((b) 9 40) ((g r) 30 0))\n(turn 40)\n");
        assertEquals(ExitCodes.OK, cli.run("convert", train, "-o", dir.resolve("t.json")), cli.err());
        for (String[] metric : new String[][] {{"continuous"}, {"cell"}, {"projection"}, {"continuous", "--matching", "optimal"}}) {
            java.util.List<Object> args = new java.util.ArrayList<>(java.util.List.of("validate", "--train", dir.resolve("t.json"),
                    "--test", dir.resolve("t.json"), "--object-weights", "0/0/0/0/0/0/0/0", "--metric"));
            args.addAll(java.util.List.of(metric));
            assertEquals(ExitCodes.OK, cli.run(args.toArray()), String.join(" ", metric) + ": " + cli.err());
            // every stored scene ties at distance 0: the first stored one (the dash) answers every query
            assertTrue(cli.out().contains("33.333 % (1 of 3)"), String.join(" ", metric) + ": " + cli.out());
        }
    }
}
