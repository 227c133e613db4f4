package org.scenes.internal.convert;

/**
 * rcssserver's see counter of one player with synchronous sees: raised once a step from the step
 * after the player's connection, a {@code see} goes out when it reaches the view width's interval
 * (1, 2, 3 steps for narrow, normal, wide) and it starts again from 0; a {@code change_view} sets
 * the interval, not the counter. So which steps get a see depends on every earlier change of
 * width. Steps are the server's (its command log counts those before kick-off as stoppage).
 */
final class SynchSeeCounter {
    /** The last step counted. */
    private long step;
    private int count;
    private int interval;
    private boolean synch;

    /**
     * @param step the step the player connected in (the counter's first rise is the next one)
     * @param interval the interval of its view width then
     * @param synch whether it sees synchronously from its connection (version 18 and later)
     */
    SynchSeeCounter(long step, int interval, boolean synch) {
        this.step = step;
        this.interval = interval;
        this.synch = synch;
    }

    boolean synch() {
        return synch;
    }

    /**
     * The player asked for synchronous sees in {@code at}: the counter runs from the next step.
     * What its asynchronous counter held then is not logged; 0 is taken.
     */
    void startSynch(long at) {
        if (!synch) {
            synch = true;
            step = at;
            count = 0;
        }
    }

    /** A change of width in {@code at}: it counts from the next step on. */
    void interval(long at, int newInterval) {
        advance(at);
        interval = newInterval;
    }

    /** Raises the counter through step {@code to}; whether a see goes out in {@code to} itself. */
    boolean advance(long to) {
        if (!synch) {
            return false;
        }
        boolean due = false;
        for (; step < to; step++) {
            due = ++count >= interval;
            if (due) {
                count = 0;
            }
        }
        return due;
    }

    /** The interval of a synchronous view width word ({@code narrow}, {@code normal}, {@code wide}), or 0. */
    static int interval(String width) {
        return switch (width) {
            case "narrow" -> 1;
            case "normal" -> 2;
            case "wide" -> 3;
            default -> 0;
        };
    }
}
