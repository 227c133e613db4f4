package org.scenes.internal.gamelog;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import org.scenes.internal.files.AtomicTextOutput;

/**
 * Writes a server command log ({@code .rcl}) in rcssserver's line format: each line starts
 * with the cycle and the stoppage time ({@code TIME,STOPPAGE}) and a tab, then either what a
 * player sent, {@code Recv TEAM_UNUM: (dash 100)}, or what the referee said,
 * {@code (referee kick_off_l)}. The file appears only on {@link #commit()}.
 */
public final class CommandLogWriter implements AutoCloseable {
    private final AtomicTextOutput output;
    private final Writer writer;

    private CommandLogWriter(Path file) throws IOException {
        this.output = AtomicTextOutput.create(file);
        this.writer = output.writer();
    }

    /** Starts a command log at {@code file} (gzipped when the name ends in {@code .gz}). */
    public static CommandLogWriter create(Path file) throws IOException {
        return new CommandLogWriter(file);
    }

    /** A message a player sent, as received (its init, commands, bye). */
    public void received(int time, int stoppage, String team, int unum, String message) throws IOException {
        writer.write(time + "," + stoppage + "\tRecv " + team + "_" + unum + ": " + oneLine(message) + "\n");
    }

    /** A referee announcement, such as {@code kick_off_l} or {@code goal_r_1}. */
    public void referee(int time, int stoppage, String announcement) throws IOException {
        writer.write(time + "," + stoppage + "\t(referee " + announcement + ")\n");
    }

    /** Finishes the log and moves it into place. */
    public Path commit() throws IOException {
        return output.commit();
    }

    /** Abandons the log unless committed. */
    @Override
    public void close() throws IOException {
        output.close();
    }

    /** A message ends at its first NUL (as the server's C string does) and stays on one line. */
    private static String oneLine(String message) {
        int nul = message.indexOf('\0');
        String text = nul >= 0 ? message.substring(0, nul) : message;
        return text.replace('\n', ' ').replace('\r', ' ');
    }
}
