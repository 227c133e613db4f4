package org.scenes.evaluate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.ToDoubleFunction;

/**
 * Teacher against imitator, figure by figure, each with its spread over the seeds; the action
 * mixes' Jensen-Shannon divergence per seed; the Turing figure; and the targets of issue 13.
 */
public record Comparison(List<Figure> figures, double[] teacherMix, double[] imitatorMix, Spread divergence,
                         TuringTest.Outcome turing, List<Target> targets, List<Long> seeds) {
    /** The order of the action mix's shares. */
    public static final List<String> ACTIONS = List.of("dash", "turn", "kick");

    /** One figure for both sides; {@code percent} figures are shares shown as %. */
    public record Figure(String key, String label, boolean percent, Spread teacher, Spread imitator) {
    }

    /** A target: what is asked, the value reached, and whether it is met. */
    public record Target(String what, String reached, boolean met) {
    }

    public static Comparison of(Evaluation.Results results) {
        List<GameFigures> teacher = results.teacher().stream().map(GameFigures::of).toList();
        List<GameFigures> imitator = results.imitator().stream().map(GameFigures::of).toList();
        List<Figure> figures = new ArrayList<>();
        figures.add(figure("dashShare", "dash share", true, teacher, imitator, f -> f.mix()[0]));
        figures.add(figure("turnShare", "turn share", true, teacher, imitator, f -> f.mix()[1]));
        figures.add(figure("kickShare", "kick share", true, teacher, imitator, f -> f.mix()[2]));
        figures.add(figure("answered", "sees answered", true, teacher, imitator, GameFigures::answered));
        figures.add(figure("kicksPer1000", "kicks / 1000 cycles", false, teacher, imitator, GameFigures::kicksPer1000));
        figures.add(figure("goalsPer1000", "goals / 1000 cycles", false, teacher, imitator, GameFigures::goalsPer1000));
        figures.add(figure("goalsAgainstPer1000", "goals against / 1000 cycles", false, teacher, imitator,
                GameFigures::goalsAgainstPer1000));
        figures.add(figure("ballDistance", "mean distance to ball (m)", false, teacher, imitator,
                GameFigures::ballDistance));
        figures.add(figure("firstTouch", "kick-off to first touch (cycles)", false, teacher, imitator,
                GameFigures::firstTouch));
        figures.add(figure("stuckShare", "stuck share", true, teacher, imitator, GameFigures::stuckShare));
        figures.add(figure("agreement", "student-driven agreement", true, teacher, imitator, GameFigures::agreement));
        figures.add(figure("typeAgreement", "agreement, action type only", true, teacher, imitator,
                GameFigures::typeAgreement));
        double[] divergences = new double[teacher.size()];
        for (int i = 0; i < teacher.size(); i++) {
            divergences[i] = jensenShannon(teacher.get(i).mix(), imitator.get(i).mix());
        }
        double[] teacherMix = pooled(teacher);
        double[] imitatorMix = pooled(imitator);
        TuringTest.Outcome turing = TuringTest.run(results.teacher(), results.imitator());
        Spread divergence = Spread.of(divergences);
        List<Long> seeds = results.teacher().stream().map(PlayedGame::seed).toList();
        return new Comparison(figures, teacherMix, imitatorMix, divergence, turing,
                targets(figures, divergence, turing), seeds);
    }

    public Figure figure(String key) {
        return figures.stream().filter(f -> f.key().equals(key)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no figure " + key));
    }

    private static List<Target> targets(List<Figure> figures, Spread divergence, TuringTest.Outcome turing) {
        Map<String, Figure> byKey = new LinkedHashMap<>();
        figures.forEach(f -> byKey.put(f.key(), f));
        List<Target> targets = new ArrayList<>();
        double goalsT = byKey.get("goalsPer1000").teacher().mean();
        double goalsI = byKey.get("goalsPer1000").imitator().mean();
        double off = goalsT == 0 ? (goalsI == 0 ? 0 : Double.POSITIVE_INFINITY) : Math.abs(goalsI - goalsT) / goalsT;
        targets.add(new Target("goals / 1000 cycles within 20% of the teacher's",
                goalsT == 0 ? String.format(java.util.Locale.ROOT, "%.2f vs %.2f", goalsI, goalsT)
                        : String.format(java.util.Locale.ROOT, "%.2f vs %.2f (%+.0f%%)", goalsI, goalsT,
                                100 * (goalsI - goalsT) / goalsT), off <= 0.2));
        targets.add(new Target("action-mix divergence <= 0.02",
                String.format(java.util.Locale.ROOT, "%.4f", divergence.mean()), divergence.mean() <= 0.02));
        double stuck = byKey.get("stuckShare").imitator().mean();
        targets.add(new Target("stuck share <= 2%", String.format(java.util.Locale.ROOT, "%.1f%%", 100 * stuck),
                stuck <= 0.02));
        double agreement = byKey.get("agreement").imitator().mean();
        targets.add(new Target("student-driven agreement >= 90%",
                String.format(java.util.Locale.ROOT, "%.1f%%", 100 * agreement), agreement >= 0.9));
        targets.add(new Target("Turing accuracy <= 60%",
                String.format(java.util.Locale.ROOT, "%.1f%%", 100 * turing.accuracy()), turing.accuracy() <= 0.6));
        return targets;
    }

    private static Figure figure(String key, String label, boolean percent, List<GameFigures> teacher,
                                 List<GameFigures> imitator, ToDoubleFunction<GameFigures> value) {
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
