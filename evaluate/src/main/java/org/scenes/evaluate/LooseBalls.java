package org.scenes.evaluate;

import java.util.List;
import java.util.Set;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/**
 * The loose balls a team had to play, from the game log's frames: moments of play on in which one
 * of its players is the nearest of all to a ball rolling slower than {@link #SLOW} m a cycle,
 * {@link #FROM} to {@link #TO} m from it (nobody has it within kicking reach), and whether the next
 * kick within {@link #WITHIN} cycles was the team's. A moment that play stops (or the game log
 * ends) within those cycles without a kick is left out, no chance to play it; one with no kick at
 * all counts as not played.
 * After each moment the next {@link #WITHIN} frames are skipped, so a ball counts once.
 *
 * <p>HELIOS base plays nearly all of them; its imitators' defenders let such balls roll
 * (docs/modern-teams.md, "Defenders and a free ball"), which the share within 1 m of the ball hides.
 *
 * @param moments loose balls nearest to a player of the team
 * @param played those the team kicked next
 */
record LooseBalls(int moments, int played) {
    static final double SLOW = 1.0;
    static final double FROM = 1.2;
    static final double TO = 3.0;
    static final int WITHIN = 10;

    static LooseBalls of(List<GameFrame> frames, Side side) {
        int moments = 0;
        int played = 0;
        int k = 0;
        while (k < frames.size()) {
            GameFrame frame = frames.get(k);
            GameFrame.BallState ball = frame.ball();
            PlayerState nearest = loose(frame) ? nearest(frame) : null;
            double distance = nearest == null ? Double.NaN : Math.hypot(nearest.x() - ball.x(), nearest.y() - ball.y());
            if (nearest == null || nearest.side() != side || !(distance >= FROM && distance <= TO)) {
                k++;
                continue;
            }
            Side kicker = null;
            // the game log's end, like a stoppage, leaves no chance
            boolean stopped = k + WITHIN >= frames.size();
            for (int j = k + 1; j < Math.min(frames.size(), k + 1 + WITHIN) && kicker == null; j++) {
                if (!frames.get(j).playMode().equals("play_on")) {
                    stopped = true;
                    break;
                }
                kicker = kicker(frames.get(j - 1), frames.get(j));
            }
            if (kicker != null || !stopped) {
                moments++;
                played += kicker == side ? 1 : 0;
            }
            k += WITHIN + 1;
        }
        return new LooseBalls(moments, played);
    }

    /** Share of the moments the team played; NaN without any. */
    double share() {
        return moments == 0 ? Double.NaN : (double) played / moments;
    }

    private static boolean loose(GameFrame frame) {
        return frame.playMode().equals("play_on") && Math.hypot(frame.ball().vx(), frame.ball().vy()) < SLOW;
    }

    private static PlayerState nearest(GameFrame frame) {
        PlayerState nearest = null;
        double best = Double.POSITIVE_INFINITY;
        for (PlayerState player : frame.players()) {
            double distance = Math.hypot(player.x() - frame.ball().x(), player.y() - frame.ball().y());
            if (distance < best) {
                best = distance;
                nearest = player;
            }
        }
        return nearest;
    }

    /** The side of a player whose kick counter rose from one frame to the next (the left's first), or null. */
    private static Side kicker(GameFrame before, GameFrame after) {
        Set<Side> kicked = Possessions.kickers(before, after);
        return kicked.isEmpty() ? null : kicked.contains(Side.LEFT) ? Side.LEFT : Side.RIGHT;
    }
}
