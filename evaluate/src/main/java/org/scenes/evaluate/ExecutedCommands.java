package org.scenes.evaluate;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.scenes.api.Side;
import org.scenes.internal.convert.BodyCommands;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.MessageParser;

/**
 * The body commands one team's players executed in a game, step by step, read from the server's
 * logs: step {@code k} leads from frame {@code k} to frame {@code k + 1}, and each player executes
 * at most one body command in a step, as the server does. From the command log ({@code .rcl}) it
 * is the first well-formed body command the player sent in the step (what the server executes,
 * whether it moved anything or not); without one, a rise of one of the game log's per-player
 * counters between the two frames (those count what took effect: rcssserver counts a kick only
 * when the ball was kickable, a move only when moves are allowed).
 */
public final class ExecutedCommands {
    /** The body commands, in the order of the executed action mix. */
    public static final List<CommandType> TYPES = List.of(CommandType.DASH, CommandType.TURN, CommandType.KICK,
            CommandType.CATCH, CommandType.TACKLE, CommandType.MOVE);

    /** Where the commands were read. */
    public enum Source {
        COMMAND_LOG("the command log (.rcl)"), COUNTERS("the game log's command counters (no .rcl)");

        private final String label;

        Source(String label) {
            this.label = label;
        }

        public String label() {
            return label;
        }
    }

    private final Source source;
    /** By step, then uniform number: the index in {@link #TYPES} plus one, 0 for no command. */
    private final byte[][] steps;

    private ExecutedCommands(Source source, byte[][] steps) {
        this.source = source;
        this.steps = steps;
    }

    public Source source() {
        return source;
    }

    /** The body command the player with uniform number {@code unum} executed in step {@code step}, or null. */
    public CommandType at(int step, int unum) {
        if (step < 0 || step >= steps.length || unum < 1 || unum >= steps[step].length) {
            return null;
        }
        int code = steps[step][unum];
        return code == 0 ? null : TYPES.get(code - 1);
    }

    /** From the rises of the game log's counters of the players on {@code side}. */
    public static ExecutedCommands fromCounters(List<GameFrame> frames, Side side) {
        int players = players(frames, side);
        byte[][] steps = new byte[Math.max(0, frames.size() - 1)][players + 1];
        PlayerState[] previous = new PlayerState[players + 1];
        for (int k = 0; k < frames.size(); k++) {
            for (PlayerState player : frames.get(k).players()) {
                if (player.side() != side) {
                    continue;
                }
                PlayerState before = previous[player.unum()];
                if (before != null && k > 0) {
                    steps[k - 1][player.unum()] = risen(before.counts(), player.counts());
                }
                previous[player.unum()] = player;
            }
        }
        return new ExecutedCommands(Source.COUNTERS, steps);
    }

    /** The first counter of {@link #TYPES} that rose, as a code, 0 for none. */
    private static byte risen(PlayerState.Counts before, PlayerState.Counts after) {
        int[] b = {before.dash(), before.turn(), before.kick(), before.catches(), before.tackle(), before.move()};
        int[] a = {after.dash(), after.turn(), after.kick(), after.catches(), after.tackle(), after.move()};
        for (int i = 0; i < a.length; i++) {
            if (a[i] > b[i]) {
                return (byte) (i + 1);
            }
        }
        return 0;
    }

    /**
     * From the command log of the game: the lines of {@code team}'s players. A line sent at
     * {@code TIME,STOPPAGE} belongs to the step leaving the frame of that clock (the frames of one
     * time counted as its stoppages 0, 1, ...). A game log may keep one frame per time (the
     * project's simulator does): the frame of a time the clock stood still at is the state after
     * its last stoppage, so of the lines mapped to one frame those of the latest stoppage count.
     */
    public static ExecutedCommands fromCommandLog(List<GameFrame> frames, Side side, String team, Path commandLog)
            throws IOException {
        int players = players(frames, side);
        byte[][] steps = new byte[Math.max(0, frames.size() - 1)][players + 1];
        int[][] setAt = new int[steps.length][players + 1];
        long[] clocks = new long[frames.size()];
        for (int k = 0; k < frames.size(); k++) {
            int time = frames.get(k).time();
            long stoppage = k > 0 && frames.get(k - 1).time() == time ? (clocks[k - 1] & 0xffffffffL) + 1 : 0;
            clocks[k] = clock(time, stoppage);
        }
        MessageParser parser = new MessageParser();
        int k = 0;
        try (CommandLogReader reader = CommandLogReader.open(commandLog)) {
            CommandLogReader.Entry entry;
            while ((entry = reader.next()) != null) {
                if (entry.referee() || !entry.team().equals(team) || entry.unum() > players) {
                    continue;
                }
                long clock = clock(entry.time(), entry.stoppage());
                while (k + 1 < clocks.length && clocks[k + 1] <= clock) {
                    k++;
                }
                int unum = entry.unum();
                if (k >= steps.length || clocks[k] > clock
                        || (steps[k][unum] != 0 && setAt[k][unum] >= entry.stoppage())) {
                    continue; // before the first frame, after the last step, or not the step's first body command
                }
                CommandType type = BodyCommands.first(parser, entry.text());
                int index = type == null ? -1 : TYPES.indexOf(type);
                if (index >= 0) {
                    steps[k][unum] = (byte) (index + 1);
                    setAt[k][unum] = entry.stoppage();
                }
            }
        }
        return new ExecutedCommands(Source.COMMAND_LOG, steps);
    }

    private static long clock(int time, long stoppage) {
        return ((long) time << 32) | stoppage;
    }

    /** The highest uniform number of the side's players in the frames. */
    static int players(List<GameFrame> frames, Side side) {
        int most = 0;
        for (GameFrame frame : frames) {
            for (PlayerState player : frame.players()) {
                if (player.side() == side) {
                    most = Math.max(most, player.unum());
                }
            }
        }
        return most;
    }
}
