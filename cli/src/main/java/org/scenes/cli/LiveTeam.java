package org.scenes.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.PlayerReport;
import org.scenes.agent.net.TeamRunner;
import org.scenes.simulator.BrainFactory;

/** Runs one team on a server until the game ends or the user stops it, then prints the players' reports. */
final class LiveTeam {
    private LiveTeam() {
    }

    static int play(ClientOptions options, int players, BrainFactory brains, long seed, boolean json,
                    PrintWriter out, PrintWriter err) throws InterruptedException {
        TeamRunner runner;
        try {
            runner = new TeamRunner(options, players, brains, seed, line -> {
                err.println("scenes: " + line);
                err.flush();
            });
        } catch (IllegalArgumentException e) {
            throw new UsageException("--players: " + e.getMessage());
        }
        // Ctrl-C and SIGTERM: every player says (bye), and the reports still get printed.
        CountDownLatch printed = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            runner.stopAndAwait();
            try {
                printed.await(2, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "scenes-stop-players");
        Runtime.getRuntime().addShutdownHook(hook);
        List<PlayerReport> reports;
        try {
            reports = runner.play();
            boolean neverConnected = reports.stream().allMatch(r -> r.outcome() == PlayerReport.Outcome.NO_SERVER);
            if (json) {
                out.println(ConfigFiles.JSON.writeValueAsString(reports));
            } else if (!neverConnected) {
                // with no server the player's one line on stderr says it all
                print(out, reports);
            }
            out.flush();
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("could not write the reports as JSON", e);
        } finally {
            printed.countDown();
            ShutdownHooks.remove(hook); // unless it is running: then it stopped the players
        }
        return TeamRunner.exitCode(reports) == 0 ? ExitCodes.OK : ExitCodes.FAILURE;
    }

    private static void print(PrintWriter out, List<PlayerReport> reports) {
        out.printf(Locale.ROOT, "%-18s %-11s %6s %6s %6s %9s %8s %8s %7s %9s  %s%n", "Player", "Outcome", "Cycles",
                "Due", "Missed", "Decisions", "Mean ms", "p99 ms", "Errors", "Malformed", "Brain");
        for (PlayerReport report : reports) {
            out.printf(Locale.ROOT, "%-18s %-11s %6d %6d %6d %9d %8.3f %8.3f %7d %9d  %s%n",
                    report.team() + " " + (report.unum() > 0 ? report.side() + report.unum() : "-"),
                    report.outcome().name().toLowerCase(Locale.ROOT).replace('_', ' '), report.cycles(), report.due(),
                    report.missed(), report.decisions(), report.decisionMeanMillis(), report.decisionP99Millis(),
                    sum(report.errors()), sum(report.malformed()), describe(report.brainCounters()));
        }
        for (PlayerReport report : reports) {
            List<String> details = new ArrayList<>();
            if (!report.reason().isEmpty()) {
                details.add(report.reason());
            }
            if (!report.errors().isEmpty()) {
                details.add("errors " + describe(report.errors()));
            }
            if (!report.malformed().isEmpty()) {
                details.add("malformed " + describe(report.malformed()));
            }
            if (!details.isEmpty()) {
                out.println(report.team() + " " + report.unum() + ": " + String.join("; ", details));
            }
        }
    }

    private static long sum(Map<String, Long> counts) {
        return counts.values().stream().mapToLong(Long::longValue).sum();
    }

    private static String describe(Map<String, Long> counts) {
        List<String> parts = new ArrayList<>();
        counts.forEach((name, count) -> parts.add(name + "=" + count));
        return String.join(" ", parts);
    }
}
