package org.scenes.internal.inference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogWriter;
import org.scenes.internal.gamelog.PlayerState;

/** A game log's commands as command log entries, at the first show's cycle and stoppage. */
class InferredCommandLogTest {
    @TempDir
    Path dir;

    /** One player a side; the left one dashes every other cycle, the counts of cycle 50 jump by two. */
    private Path game(int cycles) throws IOException {
        Path rcg = dir.resolve("g.rcg");
        try (GameLogWriter writer = GameLogWriter.create(rcg, List.of())) {
            for (int time = 0; time < cycles; time++) {
                int dashes = (time + 1) / 2 + (time >= 50 ? 2 : 0);
                List<PlayerState> players = new ArrayList<>();
                players.add(new PlayerState(Side.LEFT, 1, 0, PlayerState.STANDING, -5, 0, 0, 0, 0, 0, 'h', 90, 8000, 1,
                        1, Double.NaN, new PlayerState.Counts(0, dashes, 0, 0, 0, 0, 0, 0, 0, 0, 0)));
                players.add(new PlayerState(Side.RIGHT, 1, 0, PlayerState.STANDING, 5, 0, 0, 0, 180, 0, 'h', 90, 8000,
                        1, 1, Double.NaN, new PlayerState.Counts(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)));
                writer.write(new GameFrame(time, "play_on", "Left", "Right", 0, 0, new GameFrame.BallState(0, 0, 0, 0),
                        players));
            }
            writer.commit();
        }
        return rcg;
    }

    @Test
    void eachExecutedCommandIsAnEntryOfItsStepAndJumpsAreReported() throws IOException {
        InferredCommandLog log = InferredCommandLog.of(game(100));
        List<CommandLogReader.Entry> entries = new ArrayList<>();
        for (CommandLogReader.Entry entry = log.next(); entry != null; entry = log.next()) {
            entries.add(entry);
        }
        // the dash counted in show 1 was executed in the step from show 0; the jump at 49 to 50 is left out
        assertEquals(0, entries.get(0).time());
        assertEquals("Left", entries.get(0).team());
        assertTrue(entries.get(0).text().startsWith("(dash 0 "), entries.get(0).text());
        assertTrue(entries.stream().allMatch(e -> e.time() % 2 == 0), entries.toString());
        assertTrue(entries.stream().noneMatch(e -> e.time() == 49), "the jump gives no command");
        assertEquals(1, log.warnings().size(), log.warnings().toString());
        assertTrue(log.warnings().get(0).contains("1 player steps without inferred commands"), log.warnings().get(0));
        assertTrue(log.warnings().get(0).contains("at cycle 49 for Left_1: dash count jumps by 2"), log.warnings().get(0));
    }

    @Test
    void aGameLogCutInItsLastLineGivesTheCommandsUpToThereAndAWarning() throws IOException {
        Path rcg = game(20);
        String text = Files.readString(rcg);
        Files.writeString(rcg, text.substring(0, text.length() - 40));
        InferredCommandLog log = InferredCommandLog.of(rcg);
        assertTrue(log.size() > 5, "entries " + log.size());
        assertTrue(log.warnings().get(0).contains("the game log is cut there"), log.warnings().toString());
    }
}
