package org.scenes.evaluate;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/**
 * How long a team kept the ball, from the game log's frames. A possession begins with a kick of the
 * team after a kick of the other team or a stop of play, and lasts until the other team's next kick
 * or the next stop of play (a goal, the ball out, a foul, a catch); a step in which both teams kicked
 * ends it and begins nobody's. The log's end cuts the last one, which is left out.
 *
 * <p>HELIOS base kept the ball against itself for 61 cycles and 14 kicks on average; its imitators
 * against it for 36 cycles and under three kicks (docs/evaluation.md), which the kick count per
 * 1000 cycles hides.
 *
 * @param count the team's possessions that ended in the log
 * @param meanCycles their mean length in cycles; NaN without any
 * @param meanKicks their mean number of steps in which the team kicked; NaN without any
 */
record Possessions(int count, double meanCycles, double meanKicks) {
    static Possessions of(List<GameFrame> frames, Side side) {
        Side holder = null;
        int since = 0;
        int count = 0;
        long cycles = 0;
        int kicks = 0;
        long keptKicks = 0;
        for (int j = 1; j < frames.size(); j++) {
            GameFrame frame = frames.get(j);
            Side now;
            if (!frame.playMode().equals("play_on")) {
                now = null;
            } else {
                Set<Side> kicked = kickers(frames.get(j - 1), frame);
                if (kicked.isEmpty()) {
                    continue;
                }
                now = kicked.size() == 1 ? kicked.iterator().next() : null;
            }
            if (now == holder) {
                kicks++;
                continue;
            }
            if (holder == side) {
                count++;
                cycles += frame.time() - since;
                keptKicks += kicks;
            }
            holder = now;
            since = frame.time();
            kicks = 1;
        }
        return count == 0 ? new Possessions(0, Double.NaN, Double.NaN)
                : new Possessions(count, (double) cycles / count, (double) keptKicks / count);
    }

    /** The sides of the players whose kick counters rose from one frame to the next. */
    static Set<Side> kickers(GameFrame before, GameFrame after) {
        Set<Side> sides = EnumSet.noneOf(Side.class);
        for (PlayerState player : after.players()) {
            for (PlayerState earlier : before.players()) {
                if (earlier.side() == player.side() && earlier.unum() == player.unum()
                        && player.counts().kick() > earlier.counts().kick()) {
                    sides.add(player.side());
                }
            }
        }
        return sides;
    }
}
