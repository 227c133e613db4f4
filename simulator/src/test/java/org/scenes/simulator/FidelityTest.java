package org.scenes.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.ObjectKind;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/**
 * The Krislet teacher 5 v 5 in the simulator against the real recorded Krislet game
 * ({@code ../shared/data/krislet/classic-game1}, skipped when absent): the action mix (shares of
 * dash, turn and kick among the commands) and the mean number of objects per see agree within
 * 10 % (kicks, being rare, to a factor of two). Both distributions are printed; docs/simulator.md
 * states them.
 */
class FidelityTest {
    @TempDir
    Path directory;

    /** Commands and sees of a set of player logs. */
    static final class Mix {
        long dashes;
        long turns;
        long kicks;
        long sees;
        long objects;
        final Map<ObjectKind, Long> byKind = new EnumMap<>(ObjectKind.class);

        double share(long count) {
            return (double) count / (dashes + turns + kicks);
        }

        double perSee(long count) {
            return (double) count / sees;
        }

        String describe() {
            StringBuilder text = new StringBuilder(String.format(Locale.ROOT,
                    "dash %.3f, turn %.3f, kick %.4f of %d commands; %.2f objects per see (%d sees):",
                    share(dashes), share(turns), share(kicks), dashes + turns + kicks, perSee(objects), sees));
            byKind.forEach((kind, count) -> text.append(String.format(Locale.ROOT, " %s %.2f", kind, perSee(count))));
            return text.toString();
        }
    }

    static Mix mix(List<Path> logs) throws IOException {
        Mix mix = new Mix();
        MessageParser parser = new MessageParser();
        for (Path log : logs) {
            try (BufferedReader reader = new BufferedReader(new InputStreamReader(Inputs.open(log),
                    StandardCharsets.UTF_8))) {
                String line;
                while ((line = reader.readLine()) != null) {
                    if (line.startsWith("(dash ")) {
                        mix.dashes++;
                    } else if (line.startsWith("(turn ")) {
                        mix.turns++;
                    } else if (line.startsWith("(kick ")) {
                        mix.kicks++;
                    } else if (line.startsWith("(see ")) {
                        Message message = parser.parse(line);
                        if (message instanceof See see) {
                            mix.sees++;
                            mix.objects += see.objects().size();
                            for (VisualObject object : see.objects()) {
                                mix.byKind.merge(object.kind(), 1L, Long::sum);
                            }
                        }
                    }
                }
            }
        }
        return mix;
    }

    private static List<Path> recordedGame() throws IOException {
        Path game = SharedData.resolve("krislet/classic-game1");
        try (Stream<Path> files = Files.list(game)) {
            return files.filter(f -> f.getFileName().toString().endsWith(".lsf.gz")).sorted().toList();
        }
    }

    private static boolean fromClient(String line) {
        return line.startsWith("(init ") && !line.startsWith("(init l ") && !line.startsWith("(init r ")
                || line.startsWith("(move ") || line.startsWith("(dash ") || line.startsWith("(turn ")
                || line.startsWith("(kick ") || line.startsWith("(say ") || line.startsWith("(bye");
    }

    /**
     * The teacher alone, given the real server's messages of the recorded game in their order,
     * answers with the real Krislet's mix of dashes and turns.
     */
    @Test
    @RequiresSharedData
    void theTeacherGivenTheRecordedMessagesActsLikeTheRealKrislet() throws IOException {
        List<Path> recorded = recordedGame();
        Mix real = mix(recorded);
        Mix teacher = new Mix();
        for (Path log : recorded) {
            String team = log.getFileName().toString().replaceAll("_\\d+\\.lsf\\.gz$", "");
            org.scenes.simulator.Brain brain = org.scenes.simulator.teacher.Teachers.byName("krislet")
                    .create(team, new java.util.Random(1));
            try (BufferedReader reader = new BufferedReader(new InputStreamReader(Inputs.open(log),
                    StandardCharsets.UTF_8))) {
                String line;
                while ((line = reader.readLine()) != null) {
                    if (fromClient(line)) {
                        continue;
                    }
                    brain.receive(line, command -> {
                        if (command.startsWith("(dash ")) {
                            teacher.dashes++;
                        } else if (command.startsWith("(turn ")) {
                            teacher.turns++;
                        } else if (command.startsWith("(kick ")) {
                            teacher.kicks++;
                        }
                    });
                }
            }
        }
        System.out.println("recorded classic-game1: " + real.describe());
        System.out.println("the teacher on the recorded messages: " + teacher.describe().replaceAll(";.*", ""));
        assertEquals(real.share(real.dashes), teacher.share(teacher.dashes), 0.02, "dash share");
        assertEquals(real.share(real.turns), teacher.share(teacher.turns), 0.02, "turn share");
        assertEquals(real.dashes + real.turns + real.kicks, teacher.dashes + teacher.turns + teacher.kicks,
                0.03 * (real.dashes + real.turns + real.kicks), "as many commands");
    }

    @Test
    @RequiresSharedData
    void krisletInTheSimulatorActsAndSeesLikeTheRecordedGame() throws IOException {
        List<Path> recorded = recordedGame();
        GameResult simulated = new Simulator(SimulatorTest.krisletGame(5, 4000, 1, directory)).run(t -> { });
        Mix real = mix(recorded);
        Mix ours = mix(simulated.logs());
        System.out.println("recorded classic-game1: " + real.describe());
        System.out.println("simulated 5 v 5, 4000 cycles, seed 1: " + ours.describe());
        assertEquals(real.perSee(real.objects), ours.perSee(ours.objects), 0.10 * real.perSee(real.objects),
                "objects per see");
        assertEquals(real.perSee(real.byKind.get(ObjectKind.BALL)), ours.perSee(ours.byKind.get(ObjectKind.BALL)),
                0.05, "the ball in sight");
        assertEquals(real.share(real.dashes), ours.share(ours.dashes), 0.10 * real.share(real.dashes), "dash share");
        assertEquals(real.share(real.turns), ours.share(ours.turns), 0.10 * real.share(real.turns), "turn share");
        // Kicks are rare (55 of 26,007 commands recorded): only their order of magnitude is asserted.
        assertTrue(ours.share(ours.kicks) > 0.5 * real.share(real.kicks)
                && ours.share(ours.kicks) < 2 * real.share(real.kicks), "kick share " + ours.share(ours.kicks));
    }
}
