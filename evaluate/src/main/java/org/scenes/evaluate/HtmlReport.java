package org.scenes.evaluate;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.scenes.internal.files.AtomicOutput;

/**
 * The evaluation as one self-contained web page ({@code index.html}, nothing fetched when it is
 * opened): the targets, the figures as a table and as bars (teacher and imitator side by side,
 * error bars the spread over seeds), the Turing figure, both sides' trajectories and ball heat
 * maps on the pitch, and a replay of the first seed's game of each side.
 */
public final class HtmlReport {
    /** Game cycles of the first seed's game drawn as trajectories. */
    static final int TRAJECTORY_CYCLES = 1200;
    /** Why a report of games without a game log has no pitch. */
    public static final String NO_POSITIONS = "Not measured: mean distance to the ball, kick-off to first touch,"
            + " the paths, the ball heat maps and the replays. They need the players' and the ball's positions,"
            + " which only the server's game log has: give the directory the server writes its .rcg files to"
            + " (--server-logs DIR; scenes server --record DIR). The Turing figure then sees only the players'"
            + " commands.";

    private HtmlReport() {
    }

    /** Writes {@code DIR/index.html} atomically and returns its path. */
    public static Path write(Path directory, String title, Map<String, String> about, Comparison comparison,
                             Evaluation.Results results) throws IOException {
        Files.createDirectories(directory);
        Path file = directory.resolve("index.html");
        StringBuilder html = new StringBuilder(1 << 20);
        html.append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>")
                .append(ReplayPage.escape(title)).append("</title>\n<style>\n").append(ReplayPage.style())
                .append("table{border-collapse:collapse;margin:.5em 0 1.5em}td,th{border:1px solid #bbb;"
                        + "padding:.25em .6em;text-align:right}th:first-child,td:first-child{text-align:left}"
                        + ".met{color:#186018;font-weight:bold}.missed{color:#a01010;font-weight:bold}"
                        + ".row{display:flex;flex-wrap:wrap;gap:1em}.note{color:#555;max-width:60em}"
                        + "table.about td{text-align:left;max-width:70em}table.about th{white-space:nowrap}"
                        + ".path{white-space:nowrap}\n")
                .append("</style>\n</head>\n<body>\n<h1>").append(ReplayPage.escape(title)).append("</h1>\n");
        html.append(aboutTable(about));
        html.append("<h2>Targets</h2>\n<table>\n<tr><th>target</th><th>reached</th><th></th></tr>\n");
        for (Comparison.Target target : comparison.targets()) {
            html.append("<tr><td>").append(ReplayPage.escape(target.what())).append("</td><td>")
                    .append(ReplayPage.escape(target.reached())).append("</td><td class=\"")
                    .append(target.met() ? "met\">met" : "missed\">not met").append("</td></tr>\n");
        }
        boolean fromLogs = Stream.concat(results.teacher().stream(), results.imitator().stream())
                .allMatch(g -> g.traces().isEmpty());
        html.append("</table>\n<h2>Figures</h2>\n<p class=\"note\">");
        if (fromLogs) {
            html.append("Mean over ").append(results.teacher().size()).append(" teacher and ")
                    .append(results.imitator().size()).append(" imitator games read from the server's logs, &plusmn;"
                            + " the standard deviation over games.</p>\n");
        } else {
            html.append("Mean over ").append(comparison.seeds().size()).append(" seeds (").append(comparison.seeds())
                    .append("), &plusmn; the standard deviation over seeds. Teacher and imitator play the same seeds,"
                            + " start positions and opponent.</p>\n");
        }
        html.append(Tables.html(comparison));
        html.append("<div class=\"row\">\n");
        html.append(bars(comparison, "Action mix", "% of body commands",
                List.of("dashShare", "turnShare", "kickShare"), 100, "0.0"));
        html.append(bars(comparison, "Shares", "%", List.of("answered", "stuckShare", "agreement", "typeAgreement"),
                100, "0.0"));
        html.append(bars(comparison, "Executed action mix (game log)", "% of executed body commands",
                Comparison.EXECUTED_KEYS, 100, "0.0"));
        html.append(bars(comparison, "Tempo and repeats (game log)", "%",
                List.of("bodyPerStep", "repeatShare"), 100, "0.0"));
        html.append(bars(comparison, "Where the players are (game log)", "% of play-on frames",
                List.of("nearBall", "ballInView", "onPitch", "goalieInArea", "logStuckShare", "kickOffsTaken"), 100, "0.0"));
        html.append(bars(comparison, "Loose balls played (game log)", "% of loose balls nearest to the team",
                List.of("looseBallsPlayed"), 100, "0.0"));
        html.append(bars(comparison, "Per 1000 cycles", "per 1000 cycles",
                List.of("kicksPer1000", "goalsPer1000", "goalsAgainstPer1000"), 1, "0.00"));
        html.append(bars(comparison, "Distance to ball", "m", List.of("ballDistance"), 1, "0.0"));
        html.append(bars(comparison, "Kick-off to first touch", "cycles", List.of("firstTouch"), 1, "0.0"));
        html.append(bars(comparison, "Possession length (game log)", "cycles", List.of("possessionCycles"), 1, "0.0"));
        html.append(bars(comparison, "Kicks per possession (game log)", "kicks", List.of("possessionKicks"), 1, "0.0"));
        html.append(bars(comparison, "Kicks off the goal direction", "degrees", List.of("kickAngle"), 1, "0.0"));
        html.append(bars(comparison, "Stamina", "stamina", List.of("stamina"), 1, "0"));
        html.append("<div>").append(ReportCharts.svg(ReportCharts.turing(comparison.turing()), 420, 360))
                .append("</div>\n</div>\n");
        TuringTest.Outcome turing = comparison.turing();
        html.append(String.format(Locale.ROOT, "<p class=\"note\">Turing figure: a logistic regression on windows of"
                        + " %d cycles of each player (%d teacher and %d imitator windows), trained on the other seeds'"
                        + " games and tested on the held-out seed's (%d folds); balanced accuracy %.1f%% &plusmn; %.1f."
                        + " It sees: %s.</p>\n", TuringTest.WINDOW, turing.teacherWindows(), turing.imitatorWindows(),
                turing.folds(), 100 * turing.accuracy(), 100 * turing.spread(), String.join(", ", turing.features())));
        PlayedGame teacherGame = results.teacher().get(0);
        PlayedGame imitatorGame = results.imitator().get(0);
        boolean positions = Stream.concat(results.teacher().stream(), results.imitator().stream())
                .noneMatch(g -> g.frames().isEmpty());
        html.append("<h2>On the pitch</h2>\n");
        if (!positions) {
            html.append("<p class=\"note\">").append(ReplayPage.escape(NO_POSITIONS)).append("</p>\n");
        } else {
            html.append("<div class=\"row\">\n");
            html.append("<div>").append(ReportCharts.svg(ReportCharts.trajectories("Teacher: paths, first "
                    + TRAJECTORY_CYCLES + " cycles, seed " + teacherGame.seed(), teacherGame.frames(),
                    TRAJECTORY_CYCLES, teacherGame.side()), 600, 455)).append("</div>\n");
            html.append("<div>").append(ReportCharts.svg(ReportCharts.trajectories("Imitator: paths, first "
                    + TRAJECTORY_CYCLES + " cycles, seed " + imitatorGame.seed(), imitatorGame.frames(),
                    TRAJECTORY_CYCLES, imitatorGame.side()), 600, 455)).append("</div>\n");
            html.append("<div>").append(ReportCharts.svg(ReportCharts.heatMap(
                    "Teacher: where the ball was (play on, all seeds)", results.teacher()), 600, 425)).append("</div>\n");
            html.append("<div>").append(ReportCharts.svg(ReportCharts.heatMap(
                    "Imitator: where the ball was (play on, all seeds)", results.imitator()), 600, 425))
                    .append("</div>\n</div>\n");
            html.append(playerHeatMaps(comparison, results));
            html.append("<h2>Replay: teacher, seed ").append(teacherGame.seed()).append(", ")
                    .append(score(teacherGame)).append("</h2>\n").append(ReplayPage.section("replay-teacher",
                            teacherGame.frames()));
            html.append("<h2>Replay: imitator, seed ").append(imitatorGame.seed()).append(", ")
                    .append(score(imitatorGame)).append("</h2>\n").append(ReplayPage.section("replay-imitator",
                            imitatorGame.frames()));
        }
        html.append("<script>\n").append(ReplayPage.script()).append("</script>\n</body>\n</html>\n");
        try (AtomicOutput output = AtomicOutput.create(file)) {
            output.stream().write(html.toString().getBytes(StandardCharsets.UTF_8));
            output.commit();
        }
        return file;
    }

    /**
     * What was evaluated, one row per entry, the values left-aligned as text. A file path (a word
     * holding a '/' or ending in an extension) breaks only after a '/', never inside a name (at
     * its dashes), so a list of paths wraps between paths or directories.
     */
    private static final Pattern FILE_WORD = Pattern.compile("/|\\.[a-z]{2,4}\\b");

    static String aboutTable(Map<String, String> about) {
        StringBuilder html = new StringBuilder("<table class=\"about\">\n");
        about.forEach((key, value) -> {
            html.append("<tr><th>").append(ReplayPage.escape(key)).append("</th><td>");
            String[] words = value.split(" ", -1);
            for (int i = 0; i < words.length; i++) {
                html.append(i > 0 ? " " : "").append(FILE_WORD.matcher(words[i]).find() ? path(words[i]) : ReplayPage.escape(words[i]));
            }
            html.append("</td></tr>\n");
        });
        return html.append("</table>\n").toString();
    }

    private static String path(String word) {
        StringBuilder html = new StringBuilder();
        String[] parts = word.split("/", -1);
        for (int i = 0; i < parts.length; i++) {
            html.append("<span class=\"path\">").append(ReplayPage.escape(parts[i]))
                    .append(i + 1 < parts.length ? "/" : "").append("</span>").append(i + 1 < parts.length ? "<wbr>" : "");
        }
        return html.toString();
    }

    /**
     * Where each uniform number played (play on, all games, the team attacking towards x+), the
     * teacher's and the imitator's player side by side.
     */
    private static String playerHeatMaps(Comparison comparison, Evaluation.Results results) {
        int players = Math.max(comparison.teacherPositions().length, comparison.imitatorPositions().length) - 1;
        if (players < 1) {
            return "";
        }
        StringBuilder html = new StringBuilder("<h2>Positions by uniform number</h2>\n<p class=\"note\">Share of"
                + " play-on frames in each 5 m cell, all games, each team attacking towards the right; teacher and"
                + " imitator side by side.</p>\n<div class=\"row\">\n");
        for (int unum = 1; unum <= players; unum++) {
            html.append("<div>").append(ReportCharts.svg(ReportCharts.playerHeatMap("Teacher, player " + unum,
                    results.teacher(), unum), 300, 210)).append(ReportCharts.svg(ReportCharts.playerHeatMap(
                    "Imitator, player " + unum, results.imitator(), unum), 300, 210)).append("</div>\n");
        }
        return html.append("</div>\n").toString();
    }

    private static String score(PlayedGame game) {
        return game.result().scoreLeft() + " : " + game.result().scoreRight();
    }

    private static String bars(Comparison comparison, String title, String unit, List<String> keys, double factor,
                               String format) {
        // the figures the games gave: games read from logs have no traced ones
        List<Comparison.Figure> figures = comparison.figures().stream().filter(f -> keys.contains(f.key()))
                .sorted(Comparator.comparingInt(f -> keys.indexOf(f.key()))).toList();
        if (figures.isEmpty()) {
            return "";
        }
        return "<div>" + ReportCharts.svg(ReportCharts.bars(title, unit, figures.stream().map(Tables::shortLabel).toList(),
                figures.stream().map(Comparison.Figure::teacher).toList(),
                figures.stream().map(Comparison.Figure::imitator).toList(), factor, format),
                Math.max(320, 150 + 130 * figures.size()), 360) + "</div>\n";
    }
}
