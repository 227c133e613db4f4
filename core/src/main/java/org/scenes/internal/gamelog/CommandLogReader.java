package org.scenes.internal.gamelog;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import org.scenes.internal.files.Inputs;

/**
 * Reads a server command log ({@code .rcl}) line by line, as {@link CommandLogWriter} and
 * rcssserver write it: {@code TIME,STOPPAGE<TAB>Recv TEAM_UNUM: (command)...} for what a player
 * sent (team names may hold {@code _}: the number follows the last one; a coach's
 * {@code TEAM_Coach} has none) and {@code TIME,STOPPAGE<TAB>(referee WORD)} for the referee.
 * Plain or gzip. Lines must come in the order of the steps; errors name the file and line. One
 * exception, as rcssserver 19 writes it when a half ends on the step after a goal's kick-off: the
 * referee's calls stamped a cycle ahead of the players' lines that follow them (the break's
 * placements); such calls are read at the step of those lines, as in every other game's log.
 */
public final class CommandLogReader implements CommandSource {
    /**
     * One line of the log.
     *
     * @param team the sender's team, empty for the referee
     * @param unum the sender's uniform number, 0 for the referee and coaches
     * @param text what the player sent, or the referee's word
     */
    public record Entry(long line, int time, int stoppage, String team, int unum, String text) {
        public boolean referee() {
            return team.isEmpty();
        }

        /** Whether this entry's step comes before the step ({@code time}, {@code stoppage}). */
        public boolean before(int otherTime, int otherStoppage) {
            return time < otherTime || (time == otherTime && stoppage < otherStoppage);
        }
    }

    private final Path file;
    private final BufferedReader in;
    private long line;
    private int lastTime = Integer.MIN_VALUE;
    private int lastStoppage;
    /** Referee calls read but not yet returned, and the entry that ended them. */
    private final ArrayDeque<Entry> ready = new ArrayDeque<>();

    private CommandLogReader(Path file) throws IOException {
        this.file = file;
        this.in = new BufferedReader(new InputStreamReader(Inputs.open(file), StandardCharsets.UTF_8), 1 << 16);
    }

    public static CommandLogReader open(Path file) throws IOException {
        return new CommandLogReader(file);
    }

    @Override
    public Path file() {
        return file;
    }

    /** The next entry that is a player's message or the referee's; null at the end of the log. */
    @Override
    public Entry next() throws IOException {
        if (!ready.isEmpty()) {
            return ready.poll();
        }
        Entry entry = read();
        if (entry == null || !entry.referee()) {
            return entry;
        }
        // a run of referee calls: the line after it says whether they were stamped a cycle ahead
        List<Entry> calls = new ArrayList<>();
        while (entry != null && entry.referee()) {
            Entry previous = calls.isEmpty() ? null : calls.get(calls.size() - 1);
            if (previous != null && entry.before(previous.time(), previous.stoppage())) {
                throw outOfOrder(entry.line(), entry.time(), entry.stoppage(), previous.time(), previous.stoppage());
            }
            calls.add(entry);
            entry = read();
        }
        Entry last = calls.get(calls.size() - 1);
        boolean behind = entry != null && entry.before(last.time(), last.stoppage());
        boolean ahead = behind && entry.time() == last.time() - 1 && entry.time() >= calls.get(0).time() - 1;
        if (behind && !ahead) {
            throw outOfOrder(entry.line(), entry.time(), entry.stoppage(), last.time(), last.stoppage());
        }
        for (Entry call : calls) {
            ready.add(ahead ? new Entry(call.line(), entry.time(), entry.stoppage(), call.team(), call.unum(),
                    call.text()) : call);
        }
        if (entry != null) {
            ready.add(entry);
        }
        return ready.poll();
    }

    /** The next line's entry as it stands in the log; null at the end of the log. */
    private Entry read() throws IOException {
        String text;
        while ((text = in.readLine()) != null) {
            line++;
            if (text.isBlank()) {
                continue;
            }
            Entry entry = parse(text);
            if (entry != null) {
                return entry;
            }
        }
        return null;
    }

    /** Whether every char is a digit ({@link Character#isDigit}), without a stream (a line a command). */
    private static boolean digits(String text) {
        for (int i = 0; i < text.length(); i++) {
            if (!Character.isDigit(text.charAt(i))) {
                return false;
            }
        }
        return true;
    }

    private Entry parse(String text) throws GameLogException {
        int tab = text.indexOf('\t');
        int comma = tab < 0 ? -1 : text.lastIndexOf(',', tab);
        if (comma <= 0) {
            throw error("expected 'TIME,STOPPAGE<tab>...' as a command log line starts, found '" + shorten(text) + "'");
        }
        int time;
        int stoppage;
        try {
            time = Integer.parseInt(text.substring(0, comma));
            stoppage = Integer.parseInt(text.substring(comma + 1, tab));
        } catch (NumberFormatException e) {
            throw error("expected 'TIME,STOPPAGE' in whole numbers, found '" + shorten(text.substring(0, tab)) + "'");
        }
        if (time < lastTime || (time == lastTime && stoppage < lastStoppage)) {
            throw outOfOrder(line, time, stoppage, lastTime, lastStoppage);
        }
        String rest = text.substring(tab + 1);
        if (rest.startsWith("(referee ")) {
            // a referee call does not move the order on: it may stand a cycle ahead (next())
            int close = rest.lastIndexOf(')');
            return new Entry(line, time, stoppage, "", 0, rest.substring(9, close < 9 ? rest.length() : close).strip());
        }
        lastTime = time;
        lastStoppage = stoppage;
        if (!rest.startsWith("Recv ")) {
            return null; // other lines (a trainer's, a monitor's) say nothing of the players
        }
        int colon = rest.indexOf(": ");
        if (colon < 0) {
            throw error("expected 'Recv TEAM_UNUM: MESSAGE', found '" + shorten(rest) + "'");
        }
        String sender = rest.substring(5, colon);
        int underscore = sender.lastIndexOf('_');
        if (underscore <= 0) {
            return null; // not a player of a team
        }
        String number = sender.substring(underscore + 1);
        if (number.isEmpty() || number.length() > 3 || !digits(number)) {
            return null; // a coach (TEAM_Coach) or another client
        }
        return new Entry(line, time, stoppage, sender.substring(0, underscore), Integer.parseInt(number),
                rest.substring(colon + 2));
    }

    private GameLogException outOfOrder(long at, int time, int stoppage, int afterTime, int afterStoppage) {
        return new GameLogException(file, at, "cycle " + time + "," + stoppage + " comes after " + afterTime + ","
                + afterStoppage + ": the command log is out of order");
    }

    private GameLogException error(String problem) {
        return new GameLogException(file, line, problem);
    }

    private static String shorten(String text) {
        return text.length() <= 60 ? text : text.substring(0, 60) + "...";
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
