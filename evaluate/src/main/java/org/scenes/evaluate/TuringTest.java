package org.scenes.evaluate;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.PlayerCommand;

/**
 * Can a simple classifier tell the teacher from the imitator? Each left player's play is cut into
 * windows of {@link #WINDOW} game cycles of play on; each window becomes the {@link #FEATURES}
 * below; a logistic regression learns teacher against imitator, cross-validated by game seed
 * (trained on the other seeds' windows of both, tested on the held-out seed's), so windows of one
 * game never sit on both sides. The figure is the balanced accuracy on the held-out windows:
 * 0.5 means it cannot tell them apart, 1.0 always can.
 */
public final class TuringTest {
    /** Game cycles per window. */
    public static final int WINDOW = 50;
    /** What the classifier sees of each window, in order. */
    public static final List<String> FEATURES = List.of(
            "mean speed", "speed spread", "mean distance to ball", "mean body turn per cycle",
            "share of cycles closing on the ball", "dash share", "turn share", "kick share",
            "answered share of sees", "mean |turn moment|", "mean dash power");

    /**
     * What it sees when the games have no positions (played on a server without its game log):
     * the last six {@link #FEATURES}, those the players' own commands give.
     */
    public static final List<String> TRAFFIC_FEATURES = FEATURES.subList(5, FEATURES.size());

    /**
     * What it sees of games read from the server's logs alone (no traffic traced): the five
     * motion features of {@link #FEATURES} and what the logs tell of the executed body commands,
     * the ball and the pitch.
     */
    public static final List<String> LOG_FEATURES = List.of(
            "mean speed", "speed spread", "mean distance to ball", "mean body turn per cycle",
            "share of cycles closing on the ball", "executed dash share", "executed turn share",
            "executed kick share", "body commands per step", "repeats previous body command",
            "share within 1 m of the ball", "share inside the field lines", "mean stamina");

    /**
     * The accuracy over held-out folds and its spread, how many windows each side gave, and the
     * features the classifier saw.
     */
    public record Outcome(double accuracy, double spread, int teacherWindows, int imitatorWindows, int folds,
                          List<String> features) {
        public Outcome {
            features = List.copyOf(features);
        }
    }

    private TuringTest() {
    }

    public static Outcome run(List<PlayedGame> teacher, List<PlayedGame> imitator) {
        boolean positions = Stream.concat(teacher.stream(), imitator.stream()).noneMatch(g -> g.frames().isEmpty());
        boolean traced = Stream.concat(teacher.stream(), imitator.stream()).noneMatch(g -> g.traces().isEmpty());
        Map<Long, List<double[]>> teacherBySeed = new HashMap<>();
        Map<Long, List<double[]>> imitatorBySeed = new HashMap<>();
        int teacherCount = 0;
        int imitatorCount = 0;
        for (PlayedGame game : teacher) {
            List<double[]> windows = traced ? windows(game, positions) : logWindows(game);
            teacherBySeed.computeIfAbsent(game.seed(), s -> new ArrayList<>()).addAll(windows);
            teacherCount += windows.size();
        }
        for (PlayedGame game : imitator) {
            List<double[]> windows = traced ? windows(game, positions) : logWindows(game);
            imitatorBySeed.computeIfAbsent(game.seed(), s -> new ArrayList<>()).addAll(windows);
            imitatorCount += windows.size();
        }
        List<Long> seeds = teacher.stream().map(PlayedGame::seed).distinct().toList();
        List<Double> accuracies = new ArrayList<>();
        if (seeds.size() >= 2) {
            for (long held : seeds) {
                List<double[]> trainT = new ArrayList<>();
                List<double[]> trainI = new ArrayList<>();
                for (long seed : seeds) {
                    if (seed != held) {
                        trainT.addAll(teacherBySeed.getOrDefault(seed, List.of()));
                        trainI.addAll(imitatorBySeed.getOrDefault(seed, List.of()));
                    }
                }
                fold(trainT, trainI, teacherBySeed.getOrDefault(held, List.of()),
                        imitatorBySeed.getOrDefault(held, List.of()), accuracies);
            }
        } else {
            // one game each: alternate blocks of windows instead of seeds
            List<double[]> allT = teacherBySeed.values().stream().flatMap(List::stream).toList();
            List<double[]> allI = imitatorBySeed.values().stream().flatMap(List::stream).toList();
            int folds = 5;
            for (int f = 0; f < folds; f++) {
                List<double[]> trainT = new ArrayList<>();
                List<double[]> trainI = new ArrayList<>();
                List<double[]> testT = new ArrayList<>();
                List<double[]> testI = new ArrayList<>();
                split(allT, f, folds, trainT, testT);
                split(allI, f, folds, trainI, testI);
                fold(trainT, trainI, testT, testI, accuracies);
            }
        }
        double mean = accuracies.stream().mapToDouble(Double::doubleValue).average().orElse(Double.NaN);
        double spread = Spread.of(accuracies.stream().mapToDouble(Double::doubleValue).toArray()).sd();
        return new Outcome(mean, spread, teacherCount, imitatorCount, accuracies.size(),
                !traced ? LOG_FEATURES : positions ? FEATURES : TRAFFIC_FEATURES);
    }

    private static void split(List<double[]> all, int fold, int folds, List<double[]> train, List<double[]> test) {
        int block = Math.max(1, all.size() / folds);
        for (int i = 0; i < all.size(); i++) {
            (Math.min(i / block, folds - 1) == fold ? test : train).add(all.get(i));
        }
    }

    private static void fold(List<double[]> trainT, List<double[]> trainI, List<double[]> testT, List<double[]> testI,
                             List<Double> accuracies) {
        if (trainT.isEmpty() || trainI.isEmpty() || testT.isEmpty() || testI.isEmpty()) {
            return;
        }
        LogisticRegression model = LogisticRegression.fit(trainT, trainI);
        double teacherRight = testT.stream().filter(x -> model.probability(x) < 0.5).count() / (double) testT.size();
        double imitatorRight = testI.stream().filter(x -> model.probability(x) >= 0.5).count() / (double) testI.size();
        accuracies.add((teacherRight + imitatorRight) / 2);
    }

    /**
     * The feature vectors of one game's windows, every player of the game's side: all the
     * {@link #FEATURES} with {@code positions}, else the {@link #TRAFFIC_FEATURES}.
     */
    static List<double[]> windows(PlayedGame game, boolean positions) {
        int players = game.traces().size();
        int windowCount = game.result().cycles() / WINDOW + 1;
        double[][][] sums = new double[players][windowCount][14];
        GameFrame previous = null;
        for (GameFrame frame : game.frames()) {
            if (frame.playMode().equals("play_on") && previous != null && previous.time() == frame.time() - 1) {
                int w = Math.min(windowCount - 1, frame.time() / WINDOW);
                for (PlayerState player : frame.players()) {
                    if (player.side() != game.side() || player.unum() > players) {
                        continue;
                    }
                    PlayerState before = previous.players().stream()
                            .filter(p -> p.side() == game.side() && p.unum() == player.unum()).findFirst().orElse(null);
                    if (before == null) {
                        continue;
                    }
                    motion(sums[player.unum() - 1][w], player, before, frame, previous);
                }
            }
            previous = frame;
        }
        for (PlayerTrace trace : game.traces()) {
            for (PlayerTrace.Decision decision : trace.decisions()) {
                if (decision.paused()) {
                    continue;
                }
                double[] s = sums[trace.unum() - 1][Math.min(windowCount - 1, Math.max(0, decision.time() / WINDOW))];
                s[6]++;
                PlayerCommand command = decision.driver();
                if (command == null) {
                    continue;
                }
                s[7]++;
                if (command.type() == CommandType.DASH) {
                    s[8]++;
                    s[11] += command.first();
                } else if (command.type() == CommandType.TURN) {
                    s[9]++;
                    s[12] += Math.abs(command.first());
                } else {
                    s[10]++;
                }
            }
        }
        List<double[]> windows = new ArrayList<>();
        for (double[][] player : sums) {
            for (double[] s : player) {
                // too little play in this window to say anything: under half of it in play on (by
                // frames), or without frames under a third of its cycles in sees (about half its sees)
                if (positions ? s[0] < WINDOW / 2.0 || s[6] < 1 : s[6] < WINDOW / 3.0) {
                    continue;
                }
                double answered = Math.max(1, s[7]);
                double[] traffic = {s[8] / answered, s[9] / answered, s[10] / answered, s[7] / s[6],
                        s[9] == 0 ? 0 : s[12] / s[9], s[8] == 0 ? 0 : Math.min(100, s[11] / s[8])};
                if (!positions) {
                    windows.add(traffic);
                    continue;
                }
                double n = s[0];
                double mean = s[1] / n;
                double[] all = new double[FEATURES.size()];
                System.arraycopy(new double[] {mean, Math.sqrt(Math.max(0, s[2] / n - mean * mean)), s[3] / n,
                        s[4] / n, s[5] / n}, 0, all, 0, 5);
                System.arraycopy(traffic, 0, all, 5, traffic.length);
                windows.add(all);
            }
        }
        return windows;
    }

    /** Adds a player's step from {@code previous} to {@code frame} to the motion sums {@code s[0..5]}. */
    private static void motion(double[] s, PlayerState player, PlayerState before, GameFrame frame,
                               GameFrame previous) {
        double speed = Math.hypot(player.x() - before.x(), player.y() - before.y());
        double distance = Math.hypot(player.x() - frame.ball().x(), player.y() - frame.ball().y());
        double distanceBefore = Math.hypot(before.x() - previous.ball().x(), before.y() - previous.ball().y());
        s[0]++;
        s[1] += speed;
        s[2] += speed * speed;
        s[3] += distance;
        s[4] += Math.abs(angle(player.body() - before.body()));
        s[5] += distance < distanceBefore ? 1 : 0;
    }

    /**
     * The {@link #LOG_FEATURES} of one game's windows, every player of the game's side, from its
     * frames and executed commands alone.
     */
    static List<double[]> logWindows(PlayedGame game) {
        List<GameFrame> frames = game.frames();
        int players = ExecutedCommands.players(frames, game.side());
        int cycles = frames.isEmpty() ? 0 : frames.get(frames.size() - 1).time();
        int windowCount = cycles / WINDOW + 1;
        // 0-5 motion, 6 steps, 7 commands, 8-10 dash/turn/kick, 11 repeats, 12 near, 13 inside, 14 stamina
        double[][][] sums = new double[players + 1][windowCount][15];
        CommandType[] previousCommand = new CommandType[players + 1];
        for (int k = 1; k < frames.size(); k++) {
            GameFrame previous = frames.get(k - 1);
            GameFrame frame = frames.get(k);
            if (!frame.playMode().equals("play_on") || previous.time() != frame.time() - 1) {
                continue;
            }
            int w = Math.min(windowCount - 1, frame.time() / WINDOW);
            PlayerState[] before = LogFigures.team(previous, game.side(), players);
            for (PlayerState player : LogFigures.team(frame, game.side(), players)) {
                if (player == null || before[player.unum()] == null) {
                    continue;
                }
                double[] s = sums[player.unum()][w];
                motion(s, player, before[player.unum()], frame, previous);
                double distance = Math.hypot(player.x() - frame.ball().x(), player.y() - frame.ball().y());
                s[12] += distance <= LogFigures.NEAR ? 1 : 0;
                s[13] += Math.abs(player.x()) <= LogFigures.HALF_LENGTH
                        && Math.abs(player.y()) <= LogFigures.HALF_WIDTH ? 1 : 0;
                s[14] += player.stamina();
                if (k + 1 < frames.size()) {
                    s[6]++;
                    CommandType command = game.executed().at(k, player.unum());
                    if (command != null) {
                        s[7]++;
                        s[8] += command == CommandType.DASH ? 1 : 0;
                        s[9] += command == CommandType.TURN ? 1 : 0;
                        s[10] += command == CommandType.KICK ? 1 : 0;
                        s[11] += command == previousCommand[player.unum()] ? 1 : 0;
                        previousCommand[player.unum()] = command;
                    }
                }
            }
        }
        List<double[]> windows = new ArrayList<>();
        for (double[][] player : sums) {
            for (double[] s : player) {
                if (s[0] < WINDOW / 2.0 || s[6] < 1) {
                    continue; // under half the window in play on
                }
                double n = s[0];
                double mean = s[1] / n;
                double commands = Math.max(1, s[7]);
                windows.add(new double[] {mean, Math.sqrt(Math.max(0, s[2] / n - mean * mean)), s[3] / n, s[4] / n,
                        s[5] / n, s[8] / commands, s[9] / commands, s[10] / commands, s[7] / s[6], s[11] / commands,
                        s[12] / n, s[13] / n, s[14] / n});
            }
        }
        return windows;
    }

    private static double angle(double degrees) {
        double a = degrees % 360;
        if (a > 180) {
            a -= 360;
        } else if (a < -180) {
            a += 360;
        }
        return a;
    }
}
