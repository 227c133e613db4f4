package org.scenes.evaluate;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.scenes.internal.protocol.PlayerCommand;

/**
 * What one player saw and did, see by see: the game time of each see, a key of what it showed
 * (ball and landmarks, see {@link TracedBrain#viewKey}), whether the game was paused, the first body
 * command the driving brain sent on it and the one the shadow brain (if any) would have sent.
 */
public final class PlayerTrace {
    /** One see and the commands answering it. */
    public record Decision(int time, long viewKey, boolean paused, PlayerCommand driver, PlayerCommand shadow) {
    }

    private final int unum;
    private final List<Decision> decisions = new ArrayList<>();
    private int time;
    private long viewKey;
    private boolean paused;
    private PlayerCommand driver;
    private PlayerCommand shadow;
    private boolean open;

    PlayerTrace(int unum) {
        this.unum = unum;
    }

    public int unum() {
        return unum;
    }

    void see(int seeTime, long key, boolean pausedNow) {
        close();
        time = seeTime;
        viewKey = key;
        paused = pausedNow;
        driver = null;
        shadow = null;
        open = true;
    }

    void driverSent(PlayerCommand command) {
        if (open && driver == null) {
            driver = command;
        }
    }

    void shadowSent(PlayerCommand command) {
        if (open && shadow == null) {
            shadow = command;
        }
    }

    void close() {
        if (open) {
            decisions.add(new Decision(time, viewKey, paused, driver, shadow));
            open = false;
        }
    }

    /** Every see in order, the last one included. */
    public List<Decision> decisions() {
        close();
        return Collections.unmodifiableList(decisions);
    }
}
