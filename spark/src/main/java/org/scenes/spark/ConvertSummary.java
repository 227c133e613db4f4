package org.scenes.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.List;
import org.scenes.internal.convert.DropReason;

/**
 * The totals of a convert job, summed where the games were converted (Spark reduces them on the
 * executors), so the driver receives one small summary, not a result per log: the counts, and the
 * first warnings and failures (a line each) in the order of the games, with how many more there were.
 */
final class ConvertSummary implements Serializable {
    /** Lines of each kind kept; the rest are counted. */
    static final int LINES_KEPT = 200;

    /** A warning or failure of the game at {@code game} (its index in the job), {@code order}-th of that game. */
    record Line(int game, int order, String text) implements Serializable {
    }

    final long logs;
    final long lines;
    final long bytes;
    final long sees;
    final long repeatedSees;
    final long scenes;
    final long malformed;
    final EnumMap<DropReason, Long> dropped;
    final long written;
    final ArrayList<Line> warnings;
    final long warningCount;
    final ArrayList<Line> failures;
    final long failureCount;

    private ConvertSummary(long logs, long lines, long bytes, long sees, long repeatedSees, long scenes, long malformed,
                           EnumMap<DropReason, Long> dropped, long written, ArrayList<Line> warnings, long warningCount,
                           ArrayList<Line> failures, long failureCount) {
        this.logs = logs;
        this.lines = lines;
        this.bytes = bytes;
        this.sees = sees;
        this.repeatedSees = repeatedSees;
        this.scenes = scenes;
        this.malformed = malformed;
        this.dropped = dropped;
        this.written = written;
        this.warnings = warnings;
        this.warningCount = warningCount;
        this.failures = failures;
        this.failureCount = failureCount;
    }

    /** One game's results: each log's counts and lines, merged. */
    static ConvertSummary of(int game, List<GameConversion.LogResult> results) {
        ConvertSummary total = new ConvertSummary(0, 0, 0, 0, 0, 0, 0, new EnumMap<>(DropReason.class), 0,
                new ArrayList<>(), 0, new ArrayList<>(), 0);
        for (GameConversion.LogResult log : results) {
            ArrayList<Line> warnings = new ArrayList<>();
            for (String warning : log.warnings()) {
                warnings.add(new Line(game, (int) total.warningCount + warnings.size(), warning));
            }
            ArrayList<Line> failures = new ArrayList<>();
            if (log.error() != null) {
                failures.add(new Line(game, (int) total.failureCount, log.error()));
            }
            total = merge(total, new ConvertSummary(1, log.lines(), log.bytes(), log.sees(), log.repeatedSees(),
                    log.scenes(), log.malformed(), new EnumMap<>(log.dropped()), log.error() == null ? 1 : 0, warnings,
                    warnings.size(), failures, failures.size()));
        }
        return total;
    }

    /** Both summaries' totals; associative and commutative, as Spark's reduce needs. */
    static ConvertSummary merge(ConvertSummary a, ConvertSummary b) {
        EnumMap<DropReason, Long> dropped = new EnumMap<>(a.dropped);
        b.dropped.forEach((reason, count) -> dropped.merge(reason, count, Long::sum));
        return new ConvertSummary(a.logs + b.logs, a.lines + b.lines, a.bytes + b.bytes, a.sees + b.sees,
                a.repeatedSees + b.repeatedSees, a.scenes + b.scenes, a.malformed + b.malformed, dropped,
                a.written + b.written, first(a.warnings, b.warnings), a.warningCount + b.warningCount,
                first(a.failures, b.failures), a.failureCount + b.failureCount);
    }

    /** The first {@link #LINES_KEPT} lines of both, in the order of the games: the same whatever the merge order. */
    private static ArrayList<Line> first(List<Line> a, List<Line> b) {
        ArrayList<Line> all = new ArrayList<>(a);
        all.addAll(b);
        all.sort(Comparator.comparingInt(Line::game).thenComparingInt(Line::order));
        return new ArrayList<>(all.subList(0, Math.min(all.size(), LINES_KEPT)));
    }

    long dropped() {
        return dropped.values().stream().mapToLong(Long::longValue).sum();
    }

    long dropped(DropReason reason) {
        return dropped.getOrDefault(reason, 0L);
    }
}
