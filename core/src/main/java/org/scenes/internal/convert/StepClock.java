package org.scenes.internal.convert;

import java.io.IOException;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.GameFrame;

/**
 * The steps of the game: each show's step, counted from the game log's first (converter step 0),
 * and the server's step each command came in. A cycle has more than one step when the clock
 * stands (stoppage: before kick-off, after a goal, at half time); the game log skips some of
 * those, and the command log, read ahead, tells how many.
 */
final class StepClock {
    private final CommandsAhead commands;
    private long frames;
    private int lastTime = -1;
    private int lastStoppage;
    private String lastMode;
    private long lastStep;
    /** The current show's step, cycle and stoppage. */
    private long step;
    private int showTime = -1;
    private int showStoppage;
    /** The server's step of {@link #step} 0: the steps before the game log's first show. */
    private long serverShift;
    /** The server's step of converter step 0. */
    private long serverOffset;

    StepClock(CommandsAhead commands) {
        this.commands = commands;
    }

    /** Places the next show: its stoppage and step, from the last show's and the referee's calls. */
    void show(GameFrame frame) throws IOException {
        int time = frame.time();
        if (frames > 0 && time < lastTime) {
            // named with the game log's line by the reader
            throw new IllegalArgumentException("cycle " + time + " comes after cycle " + lastTime
                    + ": the game log is out of order");
        }
        String mode = frame.playMode();
        int stoppage = frames > 0 && time == lastTime ? lastStoppage + 1 : 0;
        if (!mode.equals(lastMode) || (time != lastTime && commands.pausedAt(time))) {
            // steps the game log skipped (before kick-off, half time): the referee's word tells
            // how many, also when the mode is the same on both sides (a kick-off not taken by half time)
            stoppage = Math.max(stoppage, commands.announced(time, mode, stoppage));
        }
        if (frames == 0) {
            // steps from 0; a standing clock's first step has stoppage 1
            step = time + Math.max(0, stoppage - 1);
            // the server's steps before: those of cycle 0 (before kick-off) when the log starts later
            serverShift = time > 0 ? commands.lastStoppageAt(0, 0) : 0;
            serverOffset = (time == 0 ? stoppage : time + serverShift + stoppage) - step;
        } else {
            step = stepAfterLast(time, stoppage);
        }
        showTime = time;
        showStoppage = stoppage;
    }

    /** The show placed last has been handed out: the next is placed after it. */
    void shown(String mode) {
        lastTime = showTime;
        lastStoppage = showStoppage;
        lastStep = step;
        lastMode = mode;
        frames++;
    }

    /** The shows handed out. */
    long frames() {
        return frames;
    }

    /** The cycle of the last show handed out, or -1. */
    int lastTime() {
        return lastTime;
    }

    /** The current show's step. */
    long step() {
        return step;
    }

    int showTime() {
        return showTime;
    }

    int showStoppage() {
        return showStoppage;
    }

    /** The server's steps before the game log's first show. */
    long serverShift() {
        return serverShift;
    }

    /** The server's step of the current show. */
    long serverStep() {
        return step + serverOffset;
    }

    /** The server's step a command log entry was received in. */
    long serverStep(CommandLogReader.Entry entry) throws IOException {
        if (entry.time() == showTime && entry.stoppage() == showStoppage) {
            return step + serverOffset;
        }
        if (frames == 0) {
            // before the first show: the clock stands before kick-off, its steps are the stoppage
            return entry.time() == 0 ? entry.stoppage() : entry.time() + serverShift + entry.stoppage();
        }
        return stepAfterLast(entry.time(), entry.stoppage()) + serverOffset;
    }

    /**
     * The converter's step of ({@code time}, {@code stoppage}), after the last show's. The
     * stoppage steps of the cycles since that show which the game log skipped (rcssserver's
     * JSON log has no show of the half-time break) the command log tells.
     */
    private long stepAfterLast(int time, int stoppage) throws IOException {
        if (time == lastTime) {
            return lastStep + stoppage - lastStoppage;
        }
        return lastStep + (time - lastTime) + stoppage + skippedStoppage(lastTime, lastStoppage, time);
    }

    /**
     * The stoppage steps the command log holds for the cycles from {@code from} (after its
     * stoppage {@code counted}) to before {@code to}, which no show between them counted.
     */
    private long skippedStoppage(int from, int counted, int to) throws IOException {
        long skipped = 0;
        for (int time = from; time < to && time <= from + 1000; time++) {
            int base = time == from ? counted : 0;
            skipped += commands.lastStoppageAt(time, base) - base;
        }
        return skipped;
    }
}
