package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.protocol.CommandType;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/** The figures of the server's logs, checked against the simulator's own games. */
class LogFiguresTest {
    private static final Pattern RECEIVED = Pattern.compile("^(\\d+),(\\d+)\tRecv Teal_(\\d+): (.*)$");
    private static final Pattern BODY = Pattern.compile("\\((dash|turn|kick|catch|tackle|move)[ )]");

    @TempDir
    Path dir;

    @Test
    void commandCountsFromTheCommandLogAreThoseTheServerLogged() throws IOException {
        GameSetup setup = new GameSetup(new GameSetup.Team("Teal", 3, Teachers.byName("krislet")),
                new GameSetup.Team("Amber", 3, Teachers.byName("krislet")), 600, 5, null);
        Simulator simulator = new Simulator(setup).recordTo(dir);
        List<GameFrame> steps = new ArrayList<>();
        simulator.run(time -> { }, steps::add);
        Path gameLog = simulator.recorded().get(0);
        Path commandLog = simulator.recorded().get(1);

        // the truth, from the .rcl's text and the simulator's frame of every step: a player's first
        // body command of the step that left each time (its last stoppage), the game not yet over
        Map<Integer, Integer> lastStoppage = new HashMap<>();
        steps.forEach(frame -> lastStoppage.merge(frame.time(), 0, (a, b) -> a + 1));
        int last = steps.get(steps.size() - 1).time();
        Map<String, String> executed = new HashMap<>();
        for (String line : Files.readAllLines(commandLog)) {
            Matcher m = RECEIVED.matcher(line);
            Matcher body = m.matches() ? BODY.matcher(m.group(4)) : null;
            int time = m.matches() ? Integer.parseInt(m.group(1)) : -1;
            if (body != null && body.find() && time < last
                    && Integer.parseInt(m.group(2)) == lastStoppage.get(time)) {
                executed.putIfAbsent(m.group(3) + "@" + time, body.group(1));
            }
        }
        long[] expected = new long[ExecutedCommands.TYPES.size()];
        executed.values().forEach(type -> expected[ExecutedCommands.TYPES.indexOf(CommandType.fromKey(type))]++);
        assertTrue(expected[0] > 500 && expected[1] > 100, "a game of dashes and turns: " + List.of(expected[0], expected[1]));

        // with a frame a step, the command log's commands are exactly those
        PlayedGame stepByStep = new PlayedGame(PlayedGame.Role.TEACHER, Side.LEFT, 1,
                new GameResult(0, 0, 0, 0, last, steps.size(), List.of()), steps, List.of(),
                ExecutedCommands.fromCommandLog(steps, Side.LEFT, "Teal", commandLog));
        LogFigures figures = LogFigures.of(stepByStep);
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i], figures.executed()[i], ExecutedCommands.TYPES.get(i) + " executed");
        }
        // and the frames' counters tell the same dashes and turns (they count every executed one)
        LogFigures fromCounters = LogFigures.of(new PlayedGame(PlayedGame.Role.TEACHER, Side.LEFT, 1,
                stepByStep.result(), steps, List.of()));
        assertEquals(figures.executed()[0], fromCounters.executed()[0], "dashes");
        assertEquals(figures.executed()[1], fromCounters.executed()[1], "turns");
        assertTrue(fromCounters.executed()[2] <= figures.executed()[2], "kicks that reached the ball are among those sent");

        // the recorded game log keeps a frame a time: the same counts but at the ends of pauses
        ServerLogGames.Game game = ServerLogGames.read(gameLog);
        assertEquals(commandLog, game.commandLog(), "the .rcl beside the .rcg is found");
        PlayedGame played = ServerLogGames.played(PlayedGame.Role.TEACHER, List.of(game), "Teal").get(0);
        assertEquals(ExecutedCommands.Source.COMMAND_LOG, played.executed().source());
        LogFigures fromLogs = LogFigures.of(played);
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i], fromLogs.executed()[i], 3 + expected[i] / 100.0, ExecutedCommands.TYPES.get(i)
                    + " executed, from the .rcg and .rcl");
        }
        assertEquals(fromLogs.kicks(), played.result().kicksLeft(), "the result's kicks are the counters'");
        assertEquals(fromCounters.kicks(), fromLogs.kicks());
    }

    @Test
    void aKickOffTheHalfsEndCutsShortIsNoChanceMissed() throws IOException {
        PlayedGame game = played(statuesAgainstMute(), "Teal");
        LogFigures played = LogFigures.of(game);
        // the left team's own kick-off called 10 and then 60 steps before time over, never taken
        LogFigures cut = LogFigures.of(withLateKickOff(game, 10));
        LogFigures missed = LogFigures.of(withLateKickOff(game, 60));
        assertEquals(played.kickOffs(), cut.kickOffs(), "cut after 10 steps: not counted");
        assertEquals(played.kickOffs() + 1, missed.kickOffs(), "60 steps without a kick: a chance missed");
        assertEquals(played.kickOffsTaken(), cut.kickOffsTaken());
        assertEquals(played.kickOffsTaken(), missed.kickOffsTaken());
    }

    /** The game log of a 400-cycle 3 v 3 game of Teal's statues against Amber's mute players. */
    private Path statuesAgainstMute() throws IOException {
        GameSetup setup = new GameSetup(new GameSetup.Team("Teal", 3, STATUES), new GameSetup.Team("Amber", 3, MUTE),
                400, 3, null);
        Simulator simulator = new Simulator(setup).recordTo(dir);
        simulator.run(time -> { });
        return simulator.recorded().get(0);
    }

    private static PlayedGame played(Path gameLog, String team) throws IOException {
        return ServerLogGames.played(PlayedGame.Role.TEACHER, List.of(ServerLogGames.read(gameLog)), team).get(0);
    }

    /** The game with its last {@code steps} frames in the left team's kick-off and a final frame of time over. */
    private static PlayedGame withLateKickOff(PlayedGame game, int steps) {
        List<GameFrame> frames = new ArrayList<>(game.frames());
        int last = frames.size() - 1;
        for (int k = last - steps; k <= last; k++) {
            GameFrame f = frames.get(k);
            frames.set(k, new GameFrame(f.time(), k == last ? "time_over" : "kick_off_l", f.leftTeam(), f.rightTeam(),
                    f.scoreLeft(), f.scoreRight(), f.ball(), f.players()));
        }
        return new PlayedGame(game.role(), game.side(), game.seed(), game.result(), frames, List.of());
    }

    @Test
    void aTeamThatStandsStillHasFiguresOneCanWorkOut() throws IOException {
        // the right team never kicks off: the second half is one long kick_off_r, no play on
        Path gameLog = statuesAgainstMute();
        PlayedGame game = played(gameLog, "Teal");
        LogFigures figures = LogFigures.of(game);
        GameFigures frameFigures = GameFigures.of(game);
        // the ball never leaves the centre spot: player 1 half a metre from it, 2 and 3 at (-10, -+20)
        for (GameFrame frame : game.frames()) {
            assertEquals(0, Math.hypot(frame.ball().x(), frame.ball().y()), 1e-9, "the ball at " + frame.time());
        }
        assertEquals(1.0 / 3, figures.nearBall(), 1e-12);
        assertEquals(1.0, figures.onPitch(), 1e-12);
        assertTrue(Double.isNaN(figures.goalieInArea()), "no goalie: " + figures.goalieInArea());
        assertEquals((0.5 + 2 * Math.hypot(10, 20)) / 3, frameFigures.ballDistance(), 1e-9);
        // every play-on step of every player lies in a long run of commands that change nothing
        assertEquals(1.0, figures.stuckShare(), 1e-12);
        // the left team kicked off once and took it; the right team never took its one
        assertEquals(1, figures.kickOffs());
        assertEquals(1, figures.kickOffsTaken());
        PlayedGame right = played(gameLog, "Amber");
        assertEquals(Side.RIGHT, right.side());
        LogFigures rightFigures = LogFigures.of(right);
        assertEquals(1, rightFigures.kickOffs());
        assertEquals(0, rightFigures.kickOffsTaken());
        assertEquals(0, rightFigures.executed()[0] + rightFigures.executed()[1] + rightFigures.executed()[2]);
        // one kick an answered see by player 1, turns by the others; all repeats after the first
        long commands = figures.executed()[0] + figures.executed()[1] + figures.executed()[2];
        assertEquals(0, figures.executed()[0], "no dash");
        assertTrue(figures.executed()[2] > 0 && figures.executed()[1] > figures.executed()[2]);
        assertEquals(3.0 / commands, 1 - figures.repeatShare(), 1e-12, "a run per player");
        assertEquals(commands / 3.0, figures.runLength(), 1e-12);
        assertTrue(Double.isNaN(figures.kickAngle()), "kicks of no power send the ball nowhere");
        assertEquals(figures.kicks(), game.result().kicksLeft());
        assertNotNull(figures.positions()[1]);
        assertEquals(-0.5, figures.positions()[1][0], 1e-9);
        assertEquals(-10, figures.positions()[3][0], 1e-9);
        assertEquals(20, Math.abs(figures.positions()[3][1]), 1e-9);
    }

    @Test
    void kickDirectionsAreMeasuredTowardsTheGoalTheTeamAttacks() {
        // a kick from (10, 5): the left team aims at (52.5, 0), the right team at (-52.5, 0)
        assertEquals(0, kickAngle(Side.LEFT, 42.5, -5), 1e-9);
        assertEquals(0, kickAngle(Side.RIGHT, -62.5, -5), 1e-9);
        assertEquals(180, kickAngle(Side.RIGHT, 62.5, 5), 1e-9);
        assertEquals(90, kickAngle(Side.LEFT, 5, 42.5), 1e-9);
    }

    @Test
    void kicksOfSetPlaysCountAsKicksButNotForTheirDirection() {
        // a kick-off passed back: a kick, but the direction figure is of kicks in play on
        List<GameFrame> frames = List.of(kickFrame(Side.LEFT, "kick_off_l", 1, 0, 0, 0),
                kickFrame(Side.LEFT, "play_on", 2, 0, -0.5, 0));
        PlayedGame game = new PlayedGame(PlayedGame.Role.TEACHER, Side.LEFT, 1,
                new GameResult(0, 0, 0, 0, 2, 2, List.of()), frames, List.of());
        LogFigures figures = LogFigures.of(game);
        assertEquals(1, figures.kicks());
        assertTrue(Double.isNaN(figures.kickAngle()), "no kick in play on: " + figures.kickAngle());
    }

    @Test
    void theGoaliesShareInItsPenaltyAreaCountsItsPlayOnFramesInItsOwnArea() {
        // left goalie: in, out in front, out beside, on the area's corner (lines count), out in a stoppage
        double[][] left = {{-50, 0}, {-30, 0}, {-40, 25}, {-36, -20.16}, {-10, 0}};
        String[] modes = {"play_on", "play_on", "play_on", "play_on", "goal_r"};
        assertEquals(2.0 / 4, goalieInArea(Side.LEFT, left, modes), 1e-12);
        // the right team's area lies at x+, so the same spots mirrored
        double[][] right = new double[left.length][];
        for (int i = 0; i < left.length; i++) {
            right[i] = new double[] {-left[i][0], left[i][1]};
        }
        assertEquals(2.0 / 4, goalieInArea(Side.RIGHT, right, modes), 1e-12);
        assertEquals(0.0, goalieInArea(Side.RIGHT, left, modes), 1e-12, "the left area is the right team's opponent's");
    }

    /** The goalie-in-area figure of a game whose goalie stands at each spot in turn, beside a field player in the area. */
    private static double goalieInArea(Side side, double[][] spots, String[] modes) {
        List<GameFrame> frames = new ArrayList<>();
        double ownGoal = side == Side.LEFT ? -50 : 50;
        for (int i = 0; i < spots.length; i++) {
            org.scenes.internal.gamelog.PlayerState.Counts none =
                    new org.scenes.internal.gamelog.PlayerState.Counts(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
            var goalie = new org.scenes.internal.gamelog.PlayerState(side, 1, 0,
                    org.scenes.internal.gamelog.PlayerState.STANDING | org.scenes.internal.gamelog.PlayerState.GOALIE,
                    spots[i][0], spots[i][1], 0, 0, 0, 0, 'h', 90, 8000, 1, 1, Double.NaN, none);
            var back = new org.scenes.internal.gamelog.PlayerState(side, 2, 0,
                    org.scenes.internal.gamelog.PlayerState.STANDING, ownGoal, 5, 0, 0, 0, 0, 'h', 90, 8000, 1, 1,
                    Double.NaN, none);
            frames.add(new GameFrame(i + 1, modes[i], "Teal", "Amber", 0, 0, new GameFrame.BallState(0, 0, 0, 0),
                    List.of(goalie, back)));
        }
        PlayedGame game = new PlayedGame(PlayedGame.Role.TEACHER, side, 1,
                new GameResult(0, 0, 0, 0, spots.length, spots.length, List.of()), frames, List.of());
        LogFigures figures = LogFigures.of(game);
        assertEquals(1.0, figures.onPitch(), 1e-12);
        return figures.goalieInArea();
    }

    @Test
    void theBallIsInViewWithinHalfTheViewWidthOfTheHeadOrWithinTheVisibleDistance() {
        GameFrame.BallState ball = new GameFrame.BallState(10, 0, 0, 0);
        // at the origin: the ball 10 m along x
        assertTrue(LogFigures.inView(looking(0, 0, 0, 0, 60), ball, 10), "straight ahead");
        assertFalse(LogFigures.inView(looking(0, 0, 40, 0, 60), ball, 10), "40 degrees off a narrow view");
        assertTrue(LogFigures.inView(looking(0, 0, 40, 0, 120), ball, 10), "within a normal view");
        assertTrue(LogFigures.inView(looking(0, 0, 90, -80, 60), ball, 10), "the head turned back to it");
        assertFalse(LogFigures.inView(looking(0, 0, 180, 0, 180), ball, 10), "behind a wide view");
        assertTrue(LogFigures.inView(looking(12, 0, 0, 0, 60), ball, 2), "behind, but within 3 m");
        // frames without view widths (old logs) leave the figure unknown
        assertTrue(Double.isNaN(viewShare(Double.NaN)));
        assertEquals(1.0, viewShare(60), 1e-12);
    }

    private static org.scenes.internal.gamelog.PlayerState looking(double x, double y, double body, double neck,
                                                                  double viewWidth) {
        return new org.scenes.internal.gamelog.PlayerState(Side.LEFT, 2, 0,
                org.scenes.internal.gamelog.PlayerState.STANDING, x, y, 0, 0, body, neck, 'h', viewWidth, 8000, 1, 1,
                Double.NaN, new org.scenes.internal.gamelog.PlayerState.Counts(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
    }

    /** The ball-in-view figure of two play-on frames of one player looking at the ball with this view width. */
    private static double viewShare(double viewWidth) {
        List<GameFrame> frames = new ArrayList<>();
        for (int time = 1; time <= 2; time++) {
            frames.add(new GameFrame(time, "play_on", "Teal", "Amber", 0, 0, new GameFrame.BallState(10, 0, 0, 0),
                    List.of(looking(0, 0, 0, 0, viewWidth))));
        }
        PlayedGame game = new PlayedGame(PlayedGame.Role.TEACHER, Side.LEFT, 1,
                new GameResult(0, 0, 0, 0, 2, 2, List.of()), frames, List.of());
        return LogFigures.of(game).ballInView();
    }

    /** The kick angle of one kick from (10, 5) that sends the ball along (vx, vy), by a player of {@code side}. */
    private static double kickAngle(Side side, double vx, double vy) {
        List<GameFrame> frames = List.of(kickFrame(side, "play_on", 1, 0, 0, 0),
                kickFrame(side, "play_on", 2, 0, vx / 100, vy / 100));
        PlayedGame game = new PlayedGame(PlayedGame.Role.TEACHER, side, 1, new GameResult(0, 0, 0, 0, 2, 2, List.of()),
                frames, List.of());
        LogFigures figures = LogFigures.of(game);
        assertEquals(1, figures.kicks());
        return figures.kickAngle();
    }

    private static GameFrame kickFrame(Side side, String playMode, int time, int kicks, double vx, double vy) {
        org.scenes.internal.gamelog.PlayerState player = new org.scenes.internal.gamelog.PlayerState(side, 1, 0, 1,
                10.5, 5, 0, 0, 0, 0, 'h', 90, 8000, 1, 1, Double.NaN,
                new org.scenes.internal.gamelog.PlayerState.Counts(kicks + time - 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
        return new GameFrame(time, playMode, "Teal", "Amber", 0, 0, new GameFrame.BallState(10, 5, vx, vy),
                List.of(player));
    }

    /** Players that move to the same spots and then do nothing. */
    private static final BrainFactory MUTE = (team, random) -> (message, send) -> {
        if (message.startsWith("(init ")) {
            int unum = Integer.parseInt(message.split(" ")[2]);
            send.accept(unum == 1 ? "(move -12 0)" : "(move -10 " + (unum == 2 ? -20 : 20) + ")");
        }
    };

    /**
     * Players that move to a spot once, then answer every see: number 1 (beside the centre spot)
     * with a kick of no power, the others with a turn of nothing.
     */
    private static final BrainFactory STATUES = (team, random) -> new org.scenes.simulator.Brain() {
        private int unum;

        @Override
        public void receive(String message, java.util.function.Consumer<String> send) {
            if (message.startsWith("(init ")) {
                unum = Integer.parseInt(message.split(" ")[2]);
                send.accept(unum == 1 ? "(move -0.5 0)" : "(move -10 " + (unum == 2 ? -20 : 20) + ")");
            } else if (message.startsWith("(see ")) {
                send.accept(unum == 1 ? "(kick 0 0)" : "(turn 0)");
            }
        }
    };
}
