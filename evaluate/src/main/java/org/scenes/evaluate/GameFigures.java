package org.scenes.evaluate;

import java.util.List;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.world.ServerDefaults;

/**
 * The behaviour figures of one team in one game. Counted while the game is not paused
 * (before kick-off, after a goal, at half time nothing a player does moves it).
 *
 * @param dashes body commands sent on sees, by type (the action mix)
 * @param answered share of sees the players answered with a body command
 * @param kicksPer1000 kicks that touched the ball per 1000 game cycles (whole team)
 * @param goalsPer1000 goals scored per 1000 game cycles
 * @param goalsAgainstPer1000 goals conceded per 1000 game cycles
 * @param ballDistance mean distance of the team's players to the ball during play on, metres
 * @param firstTouch mean cycles from a kick-off until a player of the team first has the ball
 *                   within kickable distance; NaN when it never did
 * @param stuckShare share of the answered sees that lie in runs of {@link #STUCK_RUN} or more
 *                   answered sees with the same action type while the view key did not change
 * @param agreement share of the answered sees on which the shadow (if any) sent the same action
 *                  type, and for turns the same turn sign; NaN without a shadow
 * @param typeAgreement the same, on the action type alone
 */
public record GameFigures(int dashes, int turns, int kicks, double answered, double kicksPer1000,
                          double goalsPer1000, double goalsAgainstPer1000, double ballDistance, double firstTouch,
                          double stuckShare, double agreement, double typeAgreement) {
    /** Answered sees of one action on one view that make a player stuck. */
    public static final int STUCK_RUN = 20;
    /** Player size plus ball size plus kickable margin, metres (server defaults). */
    static final double KICKABLE = ServerDefaults.KICKABLE_AREA;

    public static GameFigures of(PlayedGame game) {
        int dashes = 0;
        int turns = 0;
        int kicks = 0;
        long sees = 0;
        long answered = 0;
        long stuck = 0;
        long compared = 0;
        long agreed = 0;
        long agreedType = 0;
        for (PlayerTrace trace : game.traces()) {
            List<PlayerTrace.Decision> decisions = trace.decisions();
            int run = 0;
            PlayerTrace.Decision previous = null;
            for (PlayerTrace.Decision decision : decisions) {
                if (decision.paused()) {
                    stuck += run >= STUCK_RUN ? run : 0;
                    run = 0;
                    previous = null;
                    continue;
                }
                sees++;
                PlayerCommand command = decision.driver();
                if (command == null) {
                    continue; // a see without an answer neither extends nor breaks a run
                }
                answered++;
                switch (command.type()) {
                    case DASH -> dashes++;
                    case TURN -> turns++;
                    default -> kicks++;
                }
                if (previous != null && previous.driver().type() == command.type()
                        && previous.viewKey() == decision.viewKey()) {
                    run++;
                } else {
                    stuck += run >= STUCK_RUN ? run : 0;
                    run = 1;
                }
                previous = decision;
                if (decision.shadow() != null) {
                    compared++;
                    if (decision.shadow().type() == command.type()) {
                        agreedType++;
                        if (agree(command, decision.shadow())) {
                            agreed++;
                        }
                    }
                }
            }
            stuck += run >= STUCK_RUN ? run : 0;
        }
        double cycles = Math.max(1, game.result().cycles());
        return new GameFigures(dashes, turns, kicks, share(answered, sees),
                1000 * game.kicks() / cycles, 1000 * game.goalsFor() / cycles,
                1000 * game.goalsAgainst() / cycles, ballDistance(game.frames(), game.side()),
                firstTouch(game.frames(), game.side()),
                share(stuck, answered), share(agreed, compared), share(agreedType, compared));
    }

    /** The action mix as shares of dash, turn and kick. */
    public double[] mix() {
        double total = Math.max(1, dashes + turns + kicks);
        return new double[] {dashes / total, turns / total, kicks / total};
    }

    /** Whether two body commands agree: the same type, and for a turn the same way round. */
    static boolean agree(PlayerCommand a, PlayerCommand b) {
        return a.type() == b.type() && (a.type() != CommandType.TURN || Math.signum(a.first()) == Math.signum(b.first()));
    }

    private static double share(long part, long whole) {
        return whole == 0 ? Double.NaN : (double) part / whole;
    }

    static double ballDistance(List<GameFrame> frames, Side side) {
        double sum = 0;
        long count = 0;
        for (GameFrame frame : frames) {
            if (!frame.playMode().equals("play_on")) {
                continue;
            }
            for (PlayerState player : frame.players()) {
                if (player.side() == side) {
                    sum += Math.hypot(player.x() - frame.ball().x(), player.y() - frame.ball().y());
                    count++;
                }
            }
        }
        return count == 0 ? Double.NaN : sum / count;
    }

    /** Mean cycles from each kick-off to the team's first reach of the ball; kick-offs it never reached are left out. */
    static double firstTouch(List<GameFrame> frames, Side side) {
        double sum = 0;
        int count = 0;
        int kickOff = -1;
        String previousMode = "";
        for (GameFrame frame : frames) {
            String mode = frame.playMode();
            if (mode.startsWith("kick_off") && !previousMode.startsWith("kick_off")) {
                kickOff = frame.time();
            }
            previousMode = mode;
            if (kickOff < 0) {
                continue;
            }
            for (PlayerState player : frame.players()) {
                if (player.side() == side
                        && Math.hypot(player.x() - frame.ball().x(), player.y() - frame.ball().y()) <= KICKABLE) {
                    sum += frame.time() - kickOff;
                    count++;
                    kickOff = -1;
                    break;
                }
            }
        }
        return count == 0 ? Double.NaN : sum / count;
    }
}
