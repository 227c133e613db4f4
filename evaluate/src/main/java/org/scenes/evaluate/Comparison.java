package org.scenes.evaluate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.ToDoubleFunction;
import java.util.stream.Stream;
import org.scenes.internal.protocol.CommandType;

/**
 * Teacher against imitator, figure by figure, each with its spread over the seeds; the action
 * mixes' Jensen-Shannon divergence per seed (of the commands sent on sees, and of the commands
 * executed as the server's logs tell them); each uniform number's mean position; the Turing
 * figure; and the targets of issue 13.
 */
public record Comparison(List<Figure> figures, double[] teacherMix, double[] imitatorMix, Spread divergence,
                         double[] teacherExecutedMix, double[] imitatorExecutedMix, Spread executedDivergence,
                         double[][] teacherPositions, double[][] imitatorPositions,
                         TuringTest.Outcome turing, List<Target> targets, List<Long> seeds) {
    /** The order of the action mix's shares. */
    public static final List<String> ACTIONS = List.of("dash", "turn", "kick");

    /** Keys of the executed action mix's shares, in the order of {@link ExecutedCommands#TYPES}. */
    public static final List<String> EXECUTED_KEYS = List.of("executedDash", "executedTurn", "executedKick",
            "executedCatch", "executedTackle", "executedMove");

    /** One figure for both sides; {@code percent} figures are shares shown as %. */
    public record Figure(String key, String label, boolean percent, Spread teacher, Spread imitator) {
    }

    /** A target: what is asked, the value reached, and whether it is met. */
    public record Target(String what, String reached, boolean met) {
    }

    /**
     * Figure by figure. The figures of the players' own traffic (the mix of commands sent on sees,
     * sees answered, stuck share, agreement) are there when the games were traced (played here);
     * the {@link LogFigures} of the server's logs whenever the games have frames.
     */
    public static Comparison of(Evaluation.Results results) {
        List<GameFigures> teacher = results.teacher().stream().map(GameFigures::of).toList();
        List<GameFigures> imitator = results.imitator().stream().map(GameFigures::of).toList();
        List<LogFigures> teacherLog = results.teacher().stream().map(LogFigures::of).toList();
        List<LogFigures> imitatorLog = results.imitator().stream().map(LogFigures::of).toList();
        boolean traced = Stream.concat(results.teacher().stream(), results.imitator().stream())
                .noneMatch(g -> g.traces().isEmpty());
        List<Figure> figures = new ArrayList<>();
        if (traced) {
            figures.add(figure("dashShare", "dash share", true, teacher, imitator, f -> f.mix()[0]));
            figures.add(figure("turnShare", "turn share", true, teacher, imitator, f -> f.mix()[1]));
            figures.add(figure("kickShare", "kick share", true, teacher, imitator, f -> f.mix()[2]));
            figures.add(figure("answered", "sees answered", true, teacher, imitator, GameFigures::answered));
        }
        figures.add(figure("kicksPer1000", "kicks / 1000 cycles", false, teacher, imitator, GameFigures::kicksPer1000));
        figures.add(figure("goalsPer1000", "goals / 1000 cycles", false, teacher, imitator, GameFigures::goalsPer1000));
        figures.add(figure("goalsAgainstPer1000", "goals against / 1000 cycles", false, teacher, imitator,
                GameFigures::goalsAgainstPer1000));
        figures.add(figure("ballDistance", "mean distance to ball (m)", false, teacher, imitator,
                GameFigures::ballDistance));
        figures.add(figure("firstTouch", "kick-off to first touch (cycles)", false, teacher, imitator,
                GameFigures::firstTouch));
        if (traced) {
            figures.add(figure("stuckShare", "stuck share", true, teacher, imitator, GameFigures::stuckShare));
        }
        // agreement is the imitator's with its shadow: there whenever it had one, even beside an untraced teacher
        boolean shadowed = results.imitator().stream().noneMatch(g -> g.traces().isEmpty())
                && imitator.stream().anyMatch(f -> !Double.isNaN(f.agreement()));
        if (shadowed) {
            figures.add(figure("agreement", "student-driven agreement", true, teacher, imitator, GameFigures::agreement));
            figures.add(figure("typeAgreement", "agreement, action type only", true, teacher, imitator,
                    GameFigures::typeAgreement));
        }
        for (int i = 0; i < ExecutedCommands.TYPES.size(); i++) {
            int type = i;
            String word = ExecutedCommands.TYPES.get(i).key();
            figures.add(figure(EXECUTED_KEYS.get(i), "executed " + word + " share", true, teacherLog, imitatorLog,
                    f -> f.mix()[type]));
        }
        figures.add(figure("bodyPerStep", "body commands per player step", true, teacherLog, imitatorLog,
                LogFigures::bodyPerStep));
        figures.add(figure("repeatShare", "repeats previous body command", true, teacherLog, imitatorLog,
                LogFigures::repeatShare));
        figures.add(figure("runLength", "mean run of one body command", false, teacherLog, imitatorLog,
                LogFigures::runLength));
        figures.add(figure("nearBall", "play on within 1 m of the ball", true, teacherLog, imitatorLog,
                LogFigures::nearBall));
        figures.add(figure("ballInView", "play on with the ball in view", true, teacherLog, imitatorLog,
                LogFigures::ballInView));
        figures.add(figure("looseBallsPlayed", "loose balls played within 10 cycles", true, teacherLog, imitatorLog,
                LogFigures::looseBallsPlayed));
        figures.add(figure("possessionCycles", "possession length (cycles)", false, teacherLog, imitatorLog,
                LogFigures::possessionCycles));
        figures.add(figure("possessionKicks", "kicks per possession", false, teacherLog, imitatorLog,
                LogFigures::possessionKicks));
        figures.add(figure("onPitch", "play on inside the field lines", true, teacherLog, imitatorLog,
                LogFigures::onPitch));
        figures.add(figure("goalieInArea", "goalie in its penalty area, play on", true, teacherLog, imitatorLog,
                LogFigures::goalieInArea));
        figures.add(figure("stamina", "mean stamina in play on", false, teacherLog, imitatorLog, LogFigures::stamina));
        figures.add(figure("lowestEffort", "lowest effort", false, teacherLog, imitatorLog, LogFigures::lowestEffort));
        figures.add(figure("kickAngle", "kick direction off goal (deg)", false, teacherLog, imitatorLog,
                LogFigures::kickAngle));
        figures.add(figure("catchesPer1000", "catches / 1000 cycles", false, teacherLog, imitatorLog,
                f -> f.per1000(CommandType.CATCH)));
        figures.add(figure("kickOffs", "own kick-offs per game", false, teacherLog, imitatorLog, f -> f.kickOffs()));
        figures.add(figure("kickOffsTaken", "own kick-offs taken", true, teacherLog, imitatorLog,
                LogFigures::kickOffShare));
        figures.add(figure("logStuckShare", "stuck share (game log)", true, teacherLog, imitatorLog,
                LogFigures::stuckShare));
        int pairs = Math.min(teacher.size(), imitator.size());
        double[] divergences = new double[pairs];
        double[] executedDivergences = new double[pairs];
        for (int i = 0; i < pairs; i++) {
            divergences[i] = traced ? jensenShannon(teacher.get(i).mix(), imitator.get(i).mix()) : Double.NaN;
            executedDivergences[i] = jensenShannon(teacherLog.get(i).mix(), imitatorLog.get(i).mix());
        }
        double[] teacherMix = traced ? pooled(teacher) : new double[] {Double.NaN, Double.NaN, Double.NaN};
        double[] imitatorMix = traced ? pooled(imitator) : new double[] {Double.NaN, Double.NaN, Double.NaN};
        TuringTest.Outcome turing = TuringTest.run(results.teacher(), results.imitator());
        Spread divergence = Spread.of(divergences);
        Spread executedDivergence = Spread.of(executedDivergences);
        List<Long> seeds = results.teacher().stream().map(PlayedGame::seed).toList();
        return new Comparison(figures, teacherMix, imitatorMix, divergence, pooledExecuted(teacherLog),
                pooledExecuted(imitatorLog), executedDivergence, positions(teacherLog), positions(imitatorLog), turing,
                targets(figures, traced ? "action-mix divergence" : "executed action-mix divergence",
                        traced ? divergence : executedDivergence, turing), seeds);
    }

    /** Whether the comparison has the figure: some are measured only with traces or server logs. */
    public boolean has(String key) {
        return figures.stream().anyMatch(f -> f.key().equals(key));
    }

    public Figure figure(String key) {
        return figures.stream().filter(f -> f.key().equals(key)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no figure " + key));
    }

    private static List<Target> targets(List<Figure> figures, String divergenceLabel, Spread divergence,
                                        TuringTest.Outcome turing) {
        Map<String, Figure> byKey = new LinkedHashMap<>();
        figures.forEach(f -> byKey.put(f.key(), f));
        List<Target> targets = new ArrayList<>();
        double goalsT = byKey.get("goalsPer1000").teacher().mean();
        double goalsI = byKey.get("goalsPer1000").imitator().mean();
        double off = goalsT == 0 ? (goalsI == 0 ? 0 : Double.POSITIVE_INFINITY) : Math.abs(goalsI - goalsT) / goalsT;
        targets.add(new Target("goals / 1000 cycles within 20% of the teacher's",
                goalsT == 0 ? String.format(Locale.ROOT, "%.2f vs %.2f", goalsI, goalsT)
                        : String.format(Locale.ROOT, "%.2f vs %.2f (%+.0f%%)", goalsI, goalsT,
                                100 * (goalsI - goalsT) / goalsT), off <= 0.2));
        targets.add(new Target(divergenceLabel + " <= 0.02",
                String.format(Locale.ROOT, "%.4f", divergence.mean()), divergence.mean() <= 0.02));
        // the stuck share of the players' own traffic where there is one, else the server log's
        Figure stuckFigure = byKey.getOrDefault("stuckShare", byKey.get("logStuckShare"));
        double stuck = stuckFigure.imitator().mean();
        targets.add(new Target(stuckFigure.label() + " <= 2%",
                String.format(Locale.ROOT, "%.1f%%", 100 * stuck), stuck <= 0.02));
        if (byKey.containsKey("agreement")) {
            double agreement = byKey.get("agreement").imitator().mean();
            targets.add(new Target("student-driven agreement >= 90%",
                    String.format(Locale.ROOT, "%.1f%%", 100 * agreement), agreement >= 0.9));
        }
        targets.add(new Target("Turing accuracy <= 60%",
                String.format(Locale.ROOT, "%.1f%%", 100 * turing.accuracy()), turing.accuracy() <= 0.6));
        return targets;
    }

    private static <T> Figure figure(String key, String label, boolean percent, List<T> teacher,
                                     List<T> imitator, ToDoubleFunction<T> value) {
        return new Figure(key, label, percent, Spread.of(teacher.stream().mapToDouble(value).toArray()),
                Spread.of(imitator.stream().mapToDouble(value).toArray()));
    }

    private static double[] pooled(List<GameFigures> games) {
        double[] counts = new double[3];
        for (GameFigures g : games) {
            counts[0] += g.dashes();
            counts[1] += g.turns();
            counts[2] += g.kicks();
        }
        double total = Math.max(1, counts[0] + counts[1] + counts[2]);
        for (int i = 0; i < 3; i++) {
            counts[i] /= total;
        }
        return counts;
    }

    /** The executed commands of all the games pooled, as shares of {@link ExecutedCommands#TYPES}. */
    private static double[] pooledExecuted(List<LogFigures> games) {
        double[] counts = new double[ExecutedCommands.TYPES.size()];
        double total = 0;
        for (LogFigures g : games) {
            for (int i = 0; i < counts.length; i++) {
                counts[i] += g.executed()[i];
                total += g.executed()[i];
            }
        }
        for (int i = 0; i < counts.length; i++) {
            counts[i] = total == 0 ? Double.NaN : counts[i] / total;
        }
        return counts;
    }

    /** Per uniform number, the mean of the games' mean positions (team frame); NaN where none. */
    private static double[][] positions(List<LogFigures> games) {
        int players = games.stream().mapToInt(g -> g.positions().length - 1).max().orElse(0);
        double[][] means = new double[players + 1][];
        for (int unum = 0; unum <= players; unum++) {
            int u = unum;
            means[unum] = new double[] {
                    Spread.of(games.stream().filter(g -> g.positions().length > u).mapToDouble(g -> g.positions()[u][0])
                            .toArray()).mean(),
                    Spread.of(games.stream().filter(g -> g.positions().length > u).mapToDouble(g -> g.positions()[u][1])
                            .toArray()).mean()};
        }
        return means;
    }

    /** Jensen-Shannon divergence of two distributions in bits: 0 for equal ones, 1 for disjoint ones. */
    public static double jensenShannon(double[] p, double[] q) {
        double sum = 0;
        for (int i = 0; i < p.length; i++) {
            double m = (p[i] + q[i]) / 2;
            sum += half(p[i], m) + half(q[i], m);
        }
        return sum;
    }

    private static double half(double p, double m) {
        return p == 0 ? 0 : 0.5 * p * Math.log(p / m) / Math.log(2);
    }
}
