package org.scenes.tests;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/**
 * Player logs the project makes itself: one seeded 5 v 5 game of Krislet teachers in the embedded
 * simulator, played once per test JVM, with the team names of the recorded Krislet games
 * ({@code Carleton} left, {@code University} right), so tests written for a recorded log read one
 * of these the same way when the shared recordings are absent.
 */
public final class SimulatedGame {
    public static final int CYCLES = 3000;
    private static Path logs;

    private SimulatedGame() {
    }

    /** The log of one player, e.g. {@code log("Carleton", 1)} for {@code Carleton_1.lsf.gz}. */
    public static synchronized Path log(String team, int unum) {
        if (logs == null) {
            logs = play();
        }
        Path log = logs.resolve(team + "_" + unum + ".lsf.gz");
        if (!Files.exists(log)) {
            throw new IllegalArgumentException("the simulated game has no player " + team + " " + unum);
        }
        return log;
    }

    private static Path play() {
        try {
            Path directory = Files.createTempDirectory("scenes-simulated-game");
            Runtime.getRuntime().addShutdownHook(new Thread(() -> delete(directory)));
            new Simulator(new GameSetup(new GameSetup.Team("Carleton", 5, Teachers.byName("krislet")),
                    new GameSetup.Team("University", 5, Teachers.byName("krislet")), CYCLES, 1, directory)).run(t -> { });
            return directory;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static void delete(Path directory) {
        try (Stream<Path> files = Files.walk(directory)) {
            files.sorted(Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
        } catch (IOException e) {
            // a temporary directory left behind is harmless
        }
    }
}
