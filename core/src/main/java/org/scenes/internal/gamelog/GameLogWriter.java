package org.scenes.internal.gamelog;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import org.scenes.api.Side;
import org.scenes.internal.files.AtomicTextOutput;

/**
 * Writes a server game log ({@code .rcg}) in the text format rcssserver 19 writes by default,
 * version 6 ({@code ULG6}): the header, the parameter messages, then per frame a
 * {@code (playmode ...)} line when the play mode changed, a {@code (team ...)} line when names
 * or score changed, and the {@code (show ...)} with the ball and every player's type, state
 * flags, position, velocity, body and neck angle, view mode, focus point, stamina and command
 * counts. Like the server it records nothing before kick-off (the play mode
 * {@code before_kick_off}, also between the halves) and one frame of {@code time_over}, and
 * ends with the final {@code (team ...)} line. The file appears only on {@link #commit()}.
 *
 * <p>Frames from the simulator carry the referee's words; those that are not play modes of the
 * game log are written as the server's play mode: {@code goal_l_3} as {@code goal_l},
 * {@code half_time} as {@code before_kick_off}, {@code time_up} as {@code time_over}.
 */
public final class GameLogWriter implements AutoCloseable {
    /** The server's precision of positions and velocities, and of angles. */
    private static final double POSITION_STEP = 0.0001;
    private static final double ANGLE_STEP = 0.001;
    /** Player slots per side in a show, as the server writes them. */
    private static final int SLOTS = 11;
    private static final Pattern GOAL = Pattern.compile("goal_([lr])_\\d+");

    private final AtomicTextOutput output;
    private final Writer writer;
    private final StringBuilder line = new StringBuilder(4096);
    private String playMode;
    private String teams;
    private boolean timeOverWritten;
    private GameFrame last;

    private GameLogWriter(Path file, List<String> parameterMessages) throws IOException {
        this.output = AtomicTextOutput.create(file);
        this.writer = output.writer();
        writer.write("ULG6\n");
        for (String message : parameterMessages) {
            writer.write(message);
            writer.write('\n');
        }
    }

    /**
     * Starts a game log at {@code file} (gzipped when the name ends in {@code .gz}) with the
     * server's parameter messages ({@code server_param}, {@code player_param}, each
     * {@code player_type}) as the clients got them.
     */
    public static GameLogWriter create(Path file, List<String> parameterMessages) throws IOException {
        return new GameLogWriter(file, parameterMessages);
    }

    /** The game log's play mode for a referee's word. */
    public static String playMode(String refereeWord) {
        var goal = GOAL.matcher(refereeWord);
        if (goal.matches()) {
            return "goal_" + goal.group(1);
        }
        return switch (refereeWord) {
            case "half_time", "time_extended" -> "before_kick_off";
            case "time_up", "time_up_without_a_team" -> "time_over";
            default -> refereeWord;
        };
    }

    /** Records one frame (skipped before kick-off and after the first frame of time over). */
    public void write(GameFrame frame) throws IOException {
        String mode = playMode(frame.playMode());
        last = frame;
        if (mode.equals("before_kick_off") || timeOverWritten) {
            return;
        }
        timeOverWritten = mode.equals("time_over");
        if (!mode.equals(playMode)) {
            playMode = mode;
            writer.write("(playmode " + frame.time() + ' ' + mode + ")\n");
        }
        String teamsNow = frame.leftTeam() + ' ' + frame.rightTeam() + ' ' + frame.scoreLeft() + ' '
                + frame.scoreRight();
        if (!teamsNow.equals(teams)) {
            teams = teamsNow;
            writer.write(teamLine(frame));
        }
        writer.write(show(frame));
    }

    /** Ends the log with the final team line and moves it into place. */
    public Path commit() throws IOException {
        if (last != null) {
            writer.write(teamLine(last));
        }
        return output.commit();
    }

    /** Abandons the log unless committed. */
    @Override
    public void close() throws IOException {
        output.close();
    }

    private static String teamLine(GameFrame frame) {
        return "(team " + frame.time() + ' ' + teamName(frame.leftTeam()) + ' ' + teamName(frame.rightTeam()) + ' '
                + frame.scoreLeft() + ' ' + frame.scoreRight() + ")\n";
    }

    private static String teamName(String name) {
        return name.isEmpty() ? "null" : name;
    }

    private String show(GameFrame frame) {
        line.setLength(0);
        line.append("(show ").append(frame.time());
        GameFrame.BallState ball = frame.ball();
        line.append(" ((b)");
        position(ball.x());
        position(ball.y());
        position(ball.vx());
        position(ball.vy());
        line.append(')');
        // Like the server, all 11 slots of each side, players in them or not (readers such as
        // rcssmonitor's expect them); an empty slot is disabled: state 0.
        PlayerState[] slots = new PlayerState[2 * SLOTS];
        for (PlayerState p : frame.players()) {
            int slot = (p.side() == Side.LEFT ? 0 : SLOTS) + p.unum() - 1;
            if (p.unum() < 1 || p.unum() > SLOTS || slots[slot] != null) {
                throw new IllegalArgumentException("player " + p.side().letter() + " " + p.unum()
                        + " does not fit a game log's slots (uniform numbers 1 to 11, once each)");
            }
            slots[slot] = p;
        }
        for (int slot = 0; slot < slots.length; slot++) {
            PlayerState p = slots[slot] != null ? slots[slot] : disabled(slot < SLOTS ? Side.LEFT : Side.RIGHT, slot % SLOTS + 1);
            line.append(" ((").append(p.side().letter()).append(' ').append(p.unum()).append(") ").append(p.type())
                    .append(' ');
            // The server prints the flags as C++ hex with showbase: 0x1, 0x9, and a plain 0.
            line.append(p.state() == 0 ? "0" : "0x" + Integer.toHexString(p.state()));
            position(p.x());
            position(p.y());
            position(p.vx());
            position(p.vy());
            angle(p.body());
            angle(p.neck());
            line.append(" (v ").append(p.viewQuality()).append(' ')
                    .append(LogNumbers.format(LogNumbers.quantize(p.viewWidth(), ANGLE_STEP))).append(')');
            // The focus point of version 18+ clients; without attention to a point it is the head.
            line.append(" (fp 0 0)");
            line.append(" (s ").append(LogNumbers.format(p.stamina())).append(' ')
                    .append(LogNumbers.format(p.effort())).append(' ').append(LogNumbers.format(p.recovery()))
                    .append(' ').append(LogNumbers.format(Double.isNaN(p.capacity()) ? -1 : p.capacity()))
                    .append(')');
            PlayerState.Counts c = p.counts();
            line.append(" (c ").append(c.kick()).append(' ').append(c.dash()).append(' ').append(c.turn())
                    .append(' ').append(c.catches()).append(' ').append(c.move()).append(' ').append(c.turnNeck())
                    .append(' ').append(c.changeView()).append(' ').append(c.say()).append(' ').append(c.tackle())
                    .append(' ').append(c.pointto()).append(' ').append(c.attentionto()).append(" 0))");
        }
        return line.append(")\n").toString();
    }

    private static PlayerState disabled(Side side, int unum) {
        return new PlayerState(side, unum, 0, 0, 0, 0, 0, 0, 0, 0, 'h', 90, 0, 0, 0, Double.NaN,
                new PlayerState.Counts(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
    }

    private void position(double value) {
        line.append(' ').append(LogNumbers.format(LogNumbers.quantize(value, POSITION_STEP)));
    }

    private void angle(double value) {
        line.append(' ').append(LogNumbers.format(LogNumbers.quantize(value, ANGLE_STEP)));
    }
}
