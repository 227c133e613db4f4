package org.scenes.evaluate;

import java.util.List;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.world.ServerDefaults;

/**
 * The figures of one team in one game that the server's logs give for any team, ours or not:
 * its frames ({@code .rcg}) and the body commands its players executed ({@link ExecutedCommands},
 * from the {@code .rcl} or the frames' counters). Commands and kicks count in the steps in which
 * the game clock advances (before kick-off, after a goal and at half time it stands still and
 * nothing a player does moves the game); positions, stamina and stuck runs in frames of play on.
 * Positions are in the team's own frame: it attacks towards x+ whichever side it played.
 *
 * @param executed body commands executed, by {@link ExecutedCommands#TYPES}
 * @param bodyPerStep share of the players' steps (clock advancing) with an executed body command
 * @param repeatShare share of the executed body commands of the same type as the player's previous one
 * @param runLength mean length of a player's runs of executed body commands of one type
 * @param nearBall share of the players' play-on frames within {@link #NEAR} of the ball
 * @param ballInView share of the players' play-on frames with the ball in their view ({@link #inView}); NaN
 *                   where the log records no view widths
 * @param onPitch share of the players' play-on frames inside the field lines
 * @param goalieInArea share of the goalie's play-on frames inside its own penalty area; NaN without a goalie
 * @param stamina mean stamina over the players' play-on frames
 * @param lowestEffort the lowest effort any of the players had in the game
 * @param kicks kicks that reached the ball (rises of the kick counters), clock advancing
 * @param kickAngle mean angle, degrees, between the ball's velocity after each of those kicks in play on and
 *                  the direction from the ball to the opponent goal's centre (0 = straight at it)
 * @param kickOffs the team's own kick-offs ({@code kick_off_l} for the left team), but for those the end of
 *                 a half cut within {@link #CUT_SHORT} cycles: no chance to take them
 * @param kickOffsTaken those that turned to play on by a kick of the team
 * @param stuckShare share of the players' play-on steps lying in runs of {@link GameFigures#STUCK_RUN}
 *                   or more steps in which the player neither moved ({@link #STILL_METRES}) nor turned
 *                   ({@link #STILL_DEGREES}) although it executed body commands in at least a third
 *                   of them (acting without effect, not waiting)
 * @param looseBalls loose balls nearest to one of the team's players ({@link LooseBalls})
 * @param looseBallsPlayed share of those the team kicked next within {@link LooseBalls#WITHIN} cycles; NaN without any
 * @param possessionCycles mean length in cycles of the team's possessions ({@link Possessions}); NaN without any
 * @param possessionKicks mean number of steps of a possession in which the team kicked; NaN without any
 * @param positions per uniform number (index 1 on), the mean x and y in play on; NaN where none
 * @param cycles the game's length in cycles (the last frame's time)
 */
public record LogFigures(long[] executed, double bodyPerStep, double repeatShare, double runLength, double nearBall,
                         double ballInView,
                         double onPitch, double goalieInArea, double stamina, double lowestEffort, int kicks, double kickAngle,
                         int kickOffs, int kickOffsTaken, double stuckShare, int looseBalls, double looseBallsPlayed,
                         double possessionCycles, double possessionKicks, double[][] positions, int cycles) {
    /** Within this of the ball, metres, a player is near it. */
    public static final double NEAR = 1.0;
    /** Moved less than this, metres, in a step: the player stood still. */
    public static final double STILL_METRES = 0.05;
    /** Turned less than this, degrees, in a step: the player did not turn. */
    public static final double STILL_DEGREES = 0.5;
    /** Cycles under which a kick-off the half's end cuts was no chance: HELIOS base waits 16 to 34 before its kick. */
    static final int CUT_SHORT = 50;
    static final double HALF_LENGTH = 52.5;
    static final double HALF_WIDTH = 34;
    /** rcssserver's {@code penalty_area_length} and half its {@code penalty_area_width}, metres. */
    static final double PENALTY_AREA_LENGTH = 16.5;
    static final double PENALTY_AREA_HALF_WIDTH = 20.16;

    public static LogFigures of(PlayedGame game) {
        List<GameFrame> frames = game.frames();
        Side side = game.side();
        ExecutedCommands commands = game.executed();
        int players = ExecutedCommands.players(frames, side);
        double sign = side == Side.LEFT ? 1 : -1;
        long[] executed = new long[ExecutedCommands.TYPES.size()];
        long playerSteps = 0;
        long repeats = 0;
        long runs = 0;
        long playOnFrames = 0;
        long near = 0;
        long viewFrames = 0;
        long inView = 0;
        long inside = 0;
        long goalieFrames = 0;
        long goalieInside = 0;
        double staminaSum = 0;
        double lowestEffort = Double.NaN;
        int kicks = 0;
        int aimed = 0;
        double angleSum = 0;
        int kickOffs = 0;
        int kickOffsTaken = 0;
        long playOnSteps = 0;
        long stuck = 0;
        double[][] positions = new double[players + 1][3];
        CommandType[] previousCommand = new CommandType[players + 1];
        int[] stillRun = new int[players + 1];
        int[] stillActing = new int[players + 1];
        String ownKickOff = side == Side.LEFT ? "kick_off_l" : "kick_off_r";
        int kickOffSince = 0;
        for (int k = 0; k < frames.size(); k++) {
            GameFrame frame = frames.get(k);
            GameFrame next = k + 1 < frames.size() ? frames.get(k + 1) : null;
            boolean running = next != null && next.time() > frame.time();
            boolean playOn = frame.playMode().equals("play_on");
            PlayerState[] now = team(frame, side, players);
            PlayerState[] after = next == null ? new PlayerState[players + 1] : team(next, side, players);
            boolean teamKicked = false;
            for (int unum = 1; unum <= players; unum++) {
                PlayerState player = now[unum];
                if (player == null) {
                    continue;
                }
                lowestEffort = Double.isNaN(lowestEffort) ? player.effort() : Math.min(lowestEffort, player.effort());
                if (playOn) {
                    playOnFrames++;
                    double distance = Math.hypot(player.x() - frame.ball().x(), player.y() - frame.ball().y());
                    near += distance <= NEAR ? 1 : 0;
                    if (!Double.isNaN(player.viewWidth())) {
                        viewFrames++;
                        inView += inView(player, frame.ball(), distance) ? 1 : 0;
                    }
                    inside += Math.abs(player.x()) <= HALF_LENGTH && Math.abs(player.y()) <= HALF_WIDTH ? 1 : 0;
                    if ((player.state() & PlayerState.GOALIE) != 0) {
                        goalieFrames++;
                        goalieInside += inOwnPenaltyArea(sign * player.x(), player.y()) ? 1 : 0;
                    }
                    staminaSum += player.stamina();
                    positions[unum][0] += sign * player.x();
                    positions[unum][1] += sign * player.y();
                    positions[unum][2]++;
                }
                PlayerState later = after[unum];
                if (later == null) {
                    continue;
                }
                CommandType command = commands.at(k, unum);
                if (!running) {
                    previousCommand[unum] = null;
                } else {
                    playerSteps++;
                    if (command != null) {
                        executed[ExecutedCommands.TYPES.indexOf(command)]++;
                        if (command == previousCommand[unum]) {
                            repeats++;
                        } else {
                            runs++;
                        }
                        previousCommand[unum] = command;
                    }
                }
                int rise = later.counts().kick() - player.counts().kick();
                if (rise > 0) {
                    teamKicked = true;
                    if (running) {
                        kicks += rise;
                        GameFrame.BallState ball = next.ball();
                        // set plays (a kick-off's pass back) aim where the rules ask: a team that
                        // concedes often takes many kick-offs, which would say nothing of its play
                        if (playOn && Math.hypot(ball.vx(), ball.vy()) > 1e-6) {
                            double towardsGoal = Math.atan2(-sign * frame.ball().y(), HALF_LENGTH - sign * frame.ball().x());
                            double moving = Math.atan2(sign * ball.vy(), sign * ball.vx());
                            angleSum += Math.abs(Math.toDegrees(normalize(moving - towardsGoal)));
                            aimed++;
                        }
                    }
                }
                boolean bothPlayOn = playOn && next.playMode().equals("play_on");
                if (bothPlayOn) {
                    playOnSteps++;
                    if (Math.hypot(later.x() - player.x(), later.y() - player.y()) < STILL_METRES
                            && Math.abs(angle(later.body() - player.body())) < STILL_DEGREES) {
                        stillRun[unum]++;
                        stillActing[unum] += command != null ? 1 : 0;
                        continue;
                    }
                }
                stuck += stuck(stillRun[unum], stillActing[unum]);
                stillRun[unum] = 0;
                stillActing[unum] = 0;
            }
            boolean ownKickOffNow = frame.playMode().equals(ownKickOff);
            if (ownKickOffNow && (k == 0 || !frames.get(k - 1).playMode().equals(ownKickOff))) {
                kickOffSince = frame.time();
            }
            if (ownKickOffNow && (next == null || !next.playMode().equals(ownKickOff))
                    && !(next != null && endsHalf(next.playMode()) && next.time() - kickOffSince < CUT_SHORT)) {
                kickOffs++;
                if (next != null && next.playMode().equals("play_on") && teamKicked) {
                    kickOffsTaken++;
                }
            }
        }
        for (int unum = 1; unum <= players; unum++) {
            stuck += stuck(stillRun[unum], stillActing[unum]);
        }
        double[][] means = new double[players + 1][];
        for (int unum = 0; unum <= players; unum++) {
            double n = positions[unum][2];
            means[unum] = n == 0 ? new double[] {Double.NaN, Double.NaN}
                    : new double[] {positions[unum][0] / n, positions[unum][1] / n};
        }
        long total = 0;
        for (long count : executed) {
            total += count;
        }
        int cycles = frames.isEmpty() ? 0 : frames.get(frames.size() - 1).time();
        LooseBalls loose = LooseBalls.of(frames, side);
        Possessions possessions = Possessions.of(frames, side);
        double meanStamina = playOnFrames == 0 ? Double.NaN : staminaSum / playOnFrames;
        return new LogFigures(executed, share(total, playerSteps), share(repeats, total), share(total, runs),
                share(near, playOnFrames), share(inView, viewFrames), share(inside, playOnFrames),
                share(goalieInside, goalieFrames), meanStamina, lowestEffort, kicks,
                aimed == 0 ? Double.NaN : angleSum / aimed, kickOffs, kickOffsTaken, share(stuck, playOnSteps),
                loose.moments(), loose.share(), possessions.meanCycles(), possessions.meanKicks(), means, cycles);
    }

    /**
     * Whether the player's see shows the ball: within half its view width of where its head faces,
     * or within {@link ServerDefaults#VISIBLE_DISTANCE}, where rcssserver shows it whichever way the
     * player looks (a see comes every step or every few, by the view, and the frame tells where it
     * would look).
     */
    static boolean inView(PlayerState player, GameFrame.BallState ball, double distance) {
        double bearing = Math.toDegrees(Math.atan2(ball.y() - player.y(), ball.x() - player.x()));
        return distance <= ServerDefaults.VISIBLE_DISTANCE
                || Math.abs(angle(bearing - player.body() - player.neck())) <= player.viewWidth() / 2;
    }

    /** Whether a play mode follows only the end of a half: the pause, the game's end or the next half's kick-off. */
    private static boolean endsHalf(String playMode) {
        return playMode.equals("half_time") || playMode.equals("time_over") || playMode.startsWith("kick_off_");
    }

    /** Whether a point in the team's own frame (attacking towards x+) lies in its penalty area, lines included. */
    static boolean inOwnPenaltyArea(double x, double y) {
        return x >= -HALF_LENGTH && x <= -HALF_LENGTH + PENALTY_AREA_LENGTH && Math.abs(y) <= PENALTY_AREA_HALF_WIDTH;
    }

    /** The steps of a still run that count as stuck: all of a long one in which the player kept acting. */
    private static int stuck(int run, int acting) {
        return run >= GameFigures.STUCK_RUN && 3 * acting >= run ? run : 0;
    }

    /** The executed action mix: shares of {@link ExecutedCommands#TYPES}; NaN without commands. */
    public double[] mix() {
        long total = 0;
        for (long count : executed) {
            total += count;
        }
        double[] mix = new double[executed.length];
        for (int i = 0; i < mix.length; i++) {
            mix[i] = total == 0 ? Double.NaN : (double) executed[i] / total;
        }
        return mix;
    }

    /** Executed commands of one type per 1000 cycles. */
    public double per1000(CommandType type) {
        return cycles == 0 ? Double.NaN : 1000.0 * executed[ExecutedCommands.TYPES.indexOf(type)] / cycles;
    }

    /** Share of the team's kick-offs it took; NaN when it had none. */
    public double kickOffShare() {
        return share(kickOffsTaken, kickOffs);
    }

    /** The side's players of a frame by uniform number (index 1 on). */
    static PlayerState[] team(GameFrame frame, Side side, int players) {
        PlayerState[] team = new PlayerState[players + 1];
        for (PlayerState player : frame.players()) {
            if (player.side() == side && player.unum() <= players) {
                team[player.unum()] = player;
            }
        }
        return team;
    }

    private static double share(long part, long whole) {
        return whole == 0 ? Double.NaN : (double) part / whole;
    }

    private static double normalize(double radians) {
        return Math.atan2(Math.sin(radians), Math.cos(radians));
    }

    static double angle(double degrees) {
        double a = degrees % 360;
        if (a > 180) {
            a -= 360;
        } else if (a < -180) {
            a += 360;
        }
        return a;
    }
}
