package org.scenes.internal.convert;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandSource;
import org.scenes.internal.gamelog.GameLogWriter;

/**
 * The players' commands and the referee's calls (from the command log, or inferred from the game
 * log) read ahead of the shows: what the clock of steps and the see clocks look ahead at, until
 * each entry is taken for its step.
 */
final class CommandsAhead {
    private final CommandSource source;
    /** Entries read but not yet taken, in order. */
    private final ArrayDeque<CommandLogReader.Entry> ahead = new ArrayDeque<>();
    private boolean ended;
    private int lastTime = -1;
    /** The cycle of the last goal the referee announced. */
    private int goalCycle = -1;

    CommandsAhead(CommandSource source) {
        this.source = source;
    }

    Path file() {
        return source.file();
    }

    /** Whether the source has run out. */
    boolean ended() {
        return ended;
    }

    /** The cycle of the last entry read, or -1. */
    int lastTime() {
        return lastTime;
    }

    /** The entries read and not yet taken, in order. */
    Iterable<CommandLogReader.Entry> entries() {
        return ahead;
    }

    /** The next entry, read if need be, without taking it; null at the end. */
    CommandLogReader.Entry peek() throws IOException {
        if (ahead.isEmpty() && !readOne()) {
            return null;
        }
        return ahead.peekFirst();
    }

    /** Takes the next entry (read if need be); null at the end. */
    CommandLogReader.Entry take() throws IOException {
        if (ahead.isEmpty() && !readOne()) {
            return null;
        }
        return ahead.pollFirst();
    }

    /** The referee announced a goal in cycle {@code time} (an entry taken for its step). */
    void goalAt(int time) {
        goalCycle = time;
    }

    /** Reads ahead past {@code time}. */
    void readThrough(int time) throws IOException {
        while (!ended && (ahead.isEmpty() || ahead.peekLast().time() <= time)) {
            if (!readOne()) {
                break;
            }
        }
    }

    private boolean readOne() throws IOException {
        CommandLogReader.Entry entry = source.next();
        if (entry == null) {
            ended = true;
            return false;
        }
        ahead.addLast(entry);
        lastTime = entry.time();
        return true;
    }

    /**
     * The last step of cycle {@code time} the command log shows (its last stoppage still ahead,
     * at least {@code from}). rcssserver logs the kick-off after a goal one stoppage past the
     * cycle's last step (its players get 51 {@code sense_body} of the goal's cycle, the kick-off
     * is at stoppage 51); before kick-off and at half time, in the last step.
     */
    int lastStoppageAt(int time, int from) throws IOException {
        readThrough(time);
        int last = from;
        boolean goal = goalCycle == time;
        for (CommandLogReader.Entry entry : ahead) {
            if (entry.time() > time) {
                break;
            }
            if (entry.time() != time) {
                continue;
            }
            goal |= entry.referee() && entry.text().startsWith("goal_");
            if (!(goal && entry.referee() && entry.text().startsWith("kick_off_"))) {
                last = Math.max(last, entry.stoppage());
            }
        }
        return last;
    }

    /** The stoppage of the referee's announcement of {@code mode} at {@code time}, or -1. */
    int announced(int time, String mode, int from) throws IOException {
        readThrough(time);
        for (CommandLogReader.Entry entry : ahead) {
            if (entry.time() == time && entry.stoppage() >= from && entry.referee()
                    && GameLogWriter.playMode(entry.text()).equals(mode)) {
                return entry.stoppage();
            }
        }
        return -1;
    }

    /** Whether the referee announced {@code before_kick_off} at {@code time}: the game log skips what follows. */
    boolean pausedAt(int time) throws IOException {
        readThrough(time);
        for (CommandLogReader.Entry entry : ahead) {
            if (entry.time() > time) {
                break;
            }
            if (entry.time() == time && entry.referee()
                    && GameLogWriter.playMode(entry.text()).equals("before_kick_off")) {
                return true;
            }
        }
        return false;
    }

    /** The version of the player's init sent by the end of {@code time} (ahead of its show), or 0. */
    int initAhead(String key, int time) throws IOException {
        readThrough(time);
        for (CommandLogReader.Entry entry : ahead) {
            if (entry.time() > time) {
                break;
            }
            if (!entry.referee() && entry.text().startsWith("(init ")
                    && key.equals(entry.team() + "_" + entry.unum())) {
                return version(entry.text());
            }
        }
        return 0;
    }

    /** The protocol version of an {@code init} command; 3 when it names none. */
    static int version(String init) {
        int at = init.indexOf("(version ");
        if (at < 0) {
            return 3;
        }
        int end = init.indexOf(')', at);
        try {
            return (int) Double.parseDouble(init.substring(at + 9, end).strip());
        } catch (RuntimeException e) {
            return 3;
        }
    }
}
