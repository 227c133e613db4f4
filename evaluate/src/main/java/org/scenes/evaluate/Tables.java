package org.scenes.evaluate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** The comparison as a terminal table, an HTML table and a JSON-ready map. */
public final class Tables {
    private static final Map<String, String> SHORT = Map.ofEntries(
            Map.entry("dashShare", "dash"), Map.entry("turnShare", "turn"), Map.entry("kickShare", "kick"),
            Map.entry("answered", "sees answered"), Map.entry("stuckShare", "stuck"),
            Map.entry("agreement", "agreement"), Map.entry("typeAgreement", "type agreement"),
            Map.entry("kicksPer1000", "kicks"), Map.entry("goalsPer1000", "goals"),
            Map.entry("goalsAgainstPer1000", "goals against"), Map.entry("ballDistance", "to ball"),
            Map.entry("firstTouch", "first touch"), Map.entry("executedDash", "dash"),
            Map.entry("executedTurn", "turn"), Map.entry("executedKick", "kick"), Map.entry("executedCatch", "catch"),
            Map.entry("executedTackle", "tackle"), Map.entry("executedMove", "move"),
            Map.entry("bodyPerStep", "per step"), Map.entry("repeatShare", "repeats"), Map.entry("runLength", "run"),
            Map.entry("nearBall", "within 1 m"), Map.entry("ballInView", "ball in view"), Map.entry("looseBallsPlayed", "loose balls"),
            Map.entry("possessionCycles", "possession"), Map.entry("possessionKicks", "kicks kept"),
            Map.entry("onPitch", "on pitch"),
            Map.entry("goalieInArea", "goalie in area"), Map.entry("stamina", "stamina"),
            Map.entry("lowestEffort", "lowest effort"), Map.entry("kickAngle", "kick off goal"),
            Map.entry("catchesPer1000", "catches"), Map.entry("kickOffs", "kick-offs"),
            Map.entry("kickOffsTaken", "taken"), Map.entry("logStuckShare", "stuck (log)"));

    private Tables() {
    }

    static String shortLabel(Comparison.Figure figure) {
        return SHORT.getOrDefault(figure.key(), figure.label());
    }

    /** A plain-text table: one line per figure, teacher and imitator as mean ± sd, then the targets. */
    public static String text(Comparison comparison) {
        StringBuilder out = new StringBuilder();
        out.append(String.format(Locale.ROOT, "%-34s %18s %18s%n", "figure (" + comparison.seeds().size() + " seeds)",
                "teacher", "imitator"));
        for (Comparison.Figure figure : comparison.figures()) {
            out.append(String.format(Locale.ROOT, "%-34s %18s %18s%n", figure.label(), cell(figure, figure.teacher()),
                    cell(figure, figure.imitator())));
        }
        if (!Double.isNaN(comparison.divergence().mean())) {
            out.append(String.format(Locale.ROOT, "%-34s %18s %18s%n", "action-mix divergence (JSD, bits)", "",
                    String.format(Locale.ROOT, "%.4f ± %.4f", comparison.divergence().mean(),
                            comparison.divergence().sd())));
        }
        if (!Double.isNaN(comparison.executedDivergence().mean())) {
            out.append(String.format(Locale.ROOT, "%-34s %18s %18s%n", "executed-mix divergence (JSD)", "",
                    String.format(Locale.ROOT, "%.4f ± %.4f", comparison.executedDivergence().mean(),
                            comparison.executedDivergence().sd())));
        }
        out.append(String.format(Locale.ROOT, "%-34s %18s %18s%n", "Turing accuracy (50% = same)", "",
                String.format(Locale.ROOT, "%.1f%% ± %.1f", 100 * comparison.turing().accuracy(),
                        100 * comparison.turing().spread())));
        out.append(String.format(Locale.ROOT, "%nTargets%n"));
        for (Comparison.Target target : comparison.targets()) {
            out.append(String.format(Locale.ROOT, "  %-8s %-48s %s%n", target.met() ? "met" : "NOT MET", target.what(),
                    target.reached()));
        }
        return out.toString();
    }

    static String html(Comparison comparison) {
        StringBuilder out = new StringBuilder("<table>\n<tr><th>figure</th><th>teacher</th><th>imitator</th></tr>\n");
        for (Comparison.Figure figure : comparison.figures()) {
            out.append("<tr><td>").append(ReplayPage.escape(figure.label())).append("</td><td>")
                    .append(ReplayPage.escape(cell(figure, figure.teacher()))).append("</td><td>")
                    .append(ReplayPage.escape(cell(figure, figure.imitator()))).append("</td></tr>\n");
        }
        if (!Double.isNaN(comparison.divergence().mean())) {
            out.append(String.format(Locale.ROOT, "<tr><td>action-mix divergence (Jensen-Shannon, bits)</td><td></td>"
                    + "<td>%.4f &plusmn; %.4f</td></tr>\n", comparison.divergence().mean(), comparison.divergence().sd()));
        }
        if (!Double.isNaN(comparison.executedDivergence().mean())) {
            out.append(String.format(Locale.ROOT, "<tr><td>executed action-mix divergence (Jensen-Shannon, bits)</td>"
                    + "<td></td><td>%.4f &plusmn; %.4f</td></tr>\n", comparison.executedDivergence().mean(),
                    comparison.executedDivergence().sd()));
        }
        out.append(String.format(Locale.ROOT, "<tr><td>Turing accuracy (50%% = indistinguishable)</td><td></td>"
                + "<td>%.1f%% &plusmn; %.1f</td></tr>\n", 100 * comparison.turing().accuracy(),
                100 * comparison.turing().spread()));
        return out.append("</table>\n").toString();
    }

    private static String cell(Comparison.Figure figure, Spread spread) {
        if (Double.isNaN(spread.mean())) {
            return "-";
        }
        return figure.percent()
                ? String.format(Locale.ROOT, "%.1f%% ± %.1f", 100 * spread.mean(), 100 * spread.sd())
                : String.format(Locale.ROOT, "%.2f ± %.2f", spread.mean(), spread.sd());
    }

    /** Everything as nested maps and lists for a JSON writer. */
    public static Map<String, Object> json(Comparison comparison) {
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("seeds", comparison.seeds());
        Map<String, Object> figures = new LinkedHashMap<>();
        for (Comparison.Figure figure : comparison.figures()) {
            // ordered maps throughout: Map.of iterates in an order that changes from run to run, and so would the bytes
            Map<String, Object> sides = new LinkedHashMap<>();
            sides.put("teacher", spread(figure.teacher()));
            sides.put("imitator", spread(figure.imitator()));
            figures.put(figure.key(), sides);
        }
        root.put("figures", figures);
        root.put("actions", Comparison.ACTIONS);
        root.put("teacherMix", nullable(comparison.teacherMix()));
        root.put("imitatorMix", nullable(comparison.imitatorMix()));
        root.put("divergence", spread(comparison.divergence()));
        root.put("executedActions", ExecutedCommands.TYPES.stream().map(t -> t.key()).toList());
        root.put("teacherExecutedMix", nullable(comparison.teacherExecutedMix()));
        root.put("imitatorExecutedMix", nullable(comparison.imitatorExecutedMix()));
        root.put("executedDivergence", spread(comparison.executedDivergence()));
        Map<String, Object> positions = new LinkedHashMap<>();
        positions.put("teacher", positions(comparison.teacherPositions()));
        positions.put("imitator", positions(comparison.imitatorPositions()));
        root.put("positions", positions);
        TuringTest.Outcome turing = comparison.turing();
        Map<String, Object> t = new LinkedHashMap<>();
        t.put("accuracy", nullable(turing.accuracy()));
        t.put("spread", nullable(turing.spread()));
        t.put("folds", turing.folds());
        t.put("teacherWindows", turing.teacherWindows());
        t.put("imitatorWindows", turing.imitatorWindows());
        t.put("windowCycles", TuringTest.WINDOW);
        t.put("features", turing.features());
        root.put("turing", t);
        root.put("targets", comparison.targets().stream().map(Tables::target).toList());
        return root;
    }

    private static Map<String, Object> target(Comparison.Target target) {
        Map<String, Object> map = new LinkedHashMap<>();
        map.put("target", target.what());
        map.put("reached", target.reached());
        map.put("met", target.met());
        return map;
    }

    private static Map<String, Object> spread(Spread s) {
        Map<String, Object> map = new LinkedHashMap<>();
        map.put("mean", nullable(s.mean()));
        map.put("sd", nullable(s.sd()));
        map.put("min", nullable(s.min()));
        map.put("max", nullable(s.max()));
        return map;
    }

    /** Mean positions by uniform number ("1", "2", ...) as [x, y], the team attacking towards x+. */
    private static Map<String, Object> positions(double[][] means) {
        Map<String, Object> map = new LinkedHashMap<>();
        for (int unum = 1; unum < means.length; unum++) {
            if (!Double.isNaN(means[unum][0])) {
                map.put(Integer.toString(unum), List.of(means[unum][0], means[unum][1]));
            }
        }
        return map;
    }

    private static List<Object> nullable(double[] values) {
        List<Object> list = new ArrayList<>();
        for (double v : values) {
            list.add(nullable(v));
        }
        return list;
    }

    private static Object nullable(double v) {
        return Double.isNaN(v) || Double.isInfinite(v) ? null : v;
    }

    /** Two teams of one game side by side, one line per figure. */
    public static String match(String leftLabel, GameFigures left, String rightLabel, GameFigures right) {
        StringBuilder out = new StringBuilder();
        out.append(String.format(Locale.ROOT, "%-34s %14s %14s%n", "figure", leftLabel, rightLabel));
        Map<String, double[]> rows = rows(left, right);
        rows.forEach((label, values) -> out.append(String.format(Locale.ROOT, "%-34s %14s %14s%n", label,
                value(label, values[0]), value(label, values[1]))));
        out.append(String.format(Locale.ROOT, "%-34s %14s %14s%n", "action-mix divergence (JSD, bits)", "",
                String.format(Locale.ROOT, "%.4f", Comparison.jensenShannon(left.mix(), right.mix()))));
        return out.toString();
    }

    /** One game's figures of one team for a JSON writer. */
    public static Map<String, Object> json(GameFigures figures) {
        Map<String, Object> map = new LinkedHashMap<>();
        rows(figures, figures).forEach((label, values) -> map.put(label, nullable(values[0])));
        return map;
    }

    private static Map<String, double[]> rows(GameFigures a, GameFigures b) {
        Map<String, double[]> rows = new LinkedHashMap<>();
        rows.put("dash share", new double[] {a.mix()[0], b.mix()[0]});
        rows.put("turn share", new double[] {a.mix()[1], b.mix()[1]});
        rows.put("kick share", new double[] {a.mix()[2], b.mix()[2]});
        rows.put("sees answered", new double[] {a.answered(), b.answered()});
        rows.put("kicks / 1000 cycles", new double[] {a.kicksPer1000(), b.kicksPer1000()});
        rows.put("goals / 1000 cycles", new double[] {a.goalsPer1000(), b.goalsPer1000()});
        rows.put("mean distance to ball (m)", new double[] {a.ballDistance(), b.ballDistance()});
        rows.put("kick-off to first touch (cycles)", new double[] {a.firstTouch(), b.firstTouch()});
        rows.put("stuck share", new double[] {a.stuckShare(), b.stuckShare()});
        rows.put("agreement with shadow teacher", new double[] {a.agreement(), b.agreement()});
        return rows;
    }

    private static String value(String label, double v) {
        if (Double.isNaN(v)) {
            return "-";
        }
        boolean percent = label.contains("share") || label.contains("agreement") || label.contains("answered");
        return percent ? String.format(Locale.ROOT, "%.1f%%", 100 * v) : String.format(Locale.ROOT, "%.2f", v);
    }
}
