package org.scenes.app.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.PluginRegistry;
import org.scenes.app.Progress;
import org.scenes.app.RequestException;
import org.scenes.evaluate.Dagger;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

class EvaluatingTest {
    private static final MatchConfig BALL_GOAL = MatchConfig.DEFAULT.withMetric("ball-goal", Map.of());

    @TempDir
    Path dir;

    private final Recorded progress = new Recorded();
    private final List<String> told = new ArrayList<>();
    private final AtomicInteger registryAsked = new AtomicInteger();
    private final Supplier<PluginRegistry> registry = () -> {
        registryAsked.incrementAndGet();
        return PluginRegistry.load();
    };

    @Test
    void anImitatorLearntFromTheTeachersGamesPlaysTheSameSeedsAndMostlyAgrees() throws IOException {
        Path report = dir.resolve("report");
        Evaluating.Outcome outcome = Evaluating.run(games(1, 0, null, report), registry, progress, events());

        assertEquals(2, outcome.comparison().seeds().size());
        assertEquals(2, outcome.results().teacher().size());
        assertEquals(2, outcome.results().imitator().size());
        double agreement = outcome.comparison().figure("agreement").imitator().mean();
        assertTrue(agreement > 0.5 && agreement <= 1, "agreement " + agreement);
        assertTrue(Double.isNaN(outcome.comparison().figure("agreement").teacher().mean()), "no shadow beside the teacher");
        Map<String, String> about = outcome.about();
        assertTrue(about.get("imitator learnt from").startsWith("1 teacher games of 300 cycles against the same"
                + " opponent, seeds [1001]"), about.toString());
        assertEquals("Amber, 2 players", about.get("opponent"));
        assertEquals("2 per side of 300 cycles, seeds [1, 2]", about.get("games"));
        assertEquals("krislet in process", about.get("shadow teacher"));
        assertEquals("the embedded simulator, in process, synchronous", about.get("played on"));
        assertTrue(outcome.rounds().isEmpty());
        // the stages' progress: one training game, then both sides' two games, each counted to its end
        assertEquals(List.of("Learning 300", "Evaluating 1200"), progress.begun);
        assertEquals(300 + 1200, progress.steps.get());
        assertEquals(0, progress.open);
        assertEquals(1, registryAsked.get());
        // told as it went: the knowledge base's size, then the figures before the report was written
        assertTrue(told.get(0).matches("learnt \\d+ scenes; ball-goal .*"), told.toString());
        assertEquals("figures, report null", told.get(told.size() - 1));
        assertEquals(report.resolve("index.html"), outcome.report());
        assertTrue(Files.readString(outcome.report()).contains("krislet and its imitator"));
        Map<String, Object> json = outcome.json();
        assertEquals(about, json.get("about"));
        assertFalse(json.containsKey("rounds"));
    }

    @Test
    void daggerRoundsAreToldAsTheyEndAndTheLastOnesFiguresReturned() throws IOException {
        Evaluating.Outcome outcome = Evaluating.run(games(1, 1, dir.resolve("parted.csv"), null), registry, progress,
                events());
        assertEquals(2, outcome.rounds().size());
        Dagger.Round last = outcome.rounds().get(1);
        assertTrue(last.added() > 100, "labelled scenes added " + last.added());
        assertEquals(outcome.rounds().get(0).scenes() + last.added(), last.scenes());
        assertEquals(last.comparison(), outcome.comparison());
        assertEquals(List.of("Learning 300", "Round 0 600", "Round 1 300"), progress.begun, "the teacher's games once");
        assertTrue(told.containsAll(List.of("dagger begins", "round 0", "round 1")), told.toString());
        long rows = Files.readAllLines(dir.resolve("parted.csv")).size() - 1;
        assertTrue(outcome.about().get("disagreements").startsWith(rows + " sees on which imitator and shadow parted"),
                outcome.about().toString());
        assertNull(outcome.report());
    }

    @Test
    void existingGameLogsGiveTheFiguresWithoutPlayingOrPlugins() throws IOException {
        // Teal the one team of all four games
        Path teacher = record(dir.resolve("teacher"), "Amber", 1, 2);
        Path imitator = record(dir.resolve("imitator"), "Red", 3, 4);
        Evaluating.Outcome outcome = Evaluating.run(logs(teacher, imitator, null), registry, progress, events());

        assertEquals("Teal", outcome.about().get("team"));
        assertTrue(outcome.about().get("teacher games").startsWith("2 in " + teacher + " (game1.rcg, game2.rcg);"
                + " executed commands from their .rcl"), outcome.about().toString());
        assertEquals(2, outcome.results().imitator().size());
        double dash = outcome.comparison().figure("executedDash").teacher().mean();
        assertTrue(dash > 0.3 && dash < 1, "executed dash share " + dash);
        assertFalse(outcome.comparison().has("dashShare"), "no traffic traced: no mix of sees answered");
        assertEquals(List.of("Reading games 4"), progress.begun);
        assertEquals(4, progress.steps.get());
        assertEquals(0, registryAsked.get(), "no plugin is needed to read game logs");
        assertEquals(List.of("figures, report null"), told);
    }

    @Test
    void aRequestThatCannotBeEvaluatedIsRefusedBeforeAnyWork() throws IOException {
        RequestException seeds = assertThrows(RequestException.class,
                () -> Evaluating.run(request(0, 0, null, null, Evaluating.GameLogs.NONE), registry, progress, events()));
        assertEquals("--seeds: must be at least 1, not 0", seeds.getMessage());
        RequestException one = assertThrows(RequestException.class, () -> Evaluating.run(
                logs(dir, null, null), registry, progress, events()));
        assertEquals("--teacher-games and --imitator-games: give both (the teacher's and the imitator's game logs)",
                one.getMessage());
        RequestException team = assertThrows(RequestException.class, () -> Evaluating.run(
                logs(record(dir.resolve("t"), "Amber", 1), record(dir.resolve("i"), "Red", 2), "Red"), registry, progress, events()));
        assertTrue(team.getMessage().startsWith("--team: ") && team.getMessage().contains("Red"), team.getMessage());
        RequestException opponent = assertThrows(RequestException.class, () -> Evaluating.run(new Evaluating.Request(
                List.of(), List.of(BALL_GOAL), new Evaluating.Lineup("krislet", 2, "krislet", null, null), 300, 1, 1, 1,
                0, null, new Evaluating.Server(null, null, 60, 9), null, 0, null, null, Evaluating.GameLogs.NONE, null),
                registry, progress, events()));
        assertEquals("--teams: 'krislet' is not TEACHER:N, e.g. krislet:5", opponent.getMessage());
        RequestException server = assertThrows(RequestException.class, () -> Evaluating.run(new Evaluating.Request(
                List.of(), List.of(BALL_GOAL), new Evaluating.Lineup("krislet", 2, "krislet:2", null, null), 300, 1, 1,
                1, 0, null, new Evaluating.Server(null, dir, 60, 9), null, 0, null, null, Evaluating.GameLogs.NONE, null),
                registry, progress, events()));
        assertTrue(server.getMessage().startsWith("--server-logs: needs --server"), server.getMessage());
        // the game logs were read for the --team refusal; nothing else began
        assertEquals(List.of("Reading games 2"), progress.begun);
        assertEquals(List.of(), told);
    }

    /** Krislet teaching itself: 2 against 2, 300 cycles, seeds 1 and 2 (one with DAgger). */
    private Evaluating.Request games(int trainGames, int dagger, Path disagreements, Path report) {
        return request(dagger == 0 ? 2 : 1, dagger, disagreements, report, Evaluating.GameLogs.NONE, trainGames);
    }

    private Evaluating.Request request(int seeds, int dagger, Path disagreements, Path report,
                                       Evaluating.GameLogs logs) {
        return request(seeds, dagger, disagreements, report, logs, 1);
    }

    private Evaluating.Request request(int seeds, int dagger, Path disagreements, Path report, Evaluating.GameLogs logs,
                                       int trainGames) {
        return new Evaluating.Request(List.of(), List.of(BALL_GOAL),
                new Evaluating.Lineup("krislet", 2, "krislet:2", null, null), 300, seeds, 1, trainGames, 0, null,
                new Evaluating.Server(null, null, 60, 9), null, dagger, null, disagreements, logs, report);
    }

    private Evaluating.Request logs(Path teacher, Path imitator, String team) {
        return new Evaluating.Request(List.of(), List.of(), new Evaluating.Lineup("krislet", 5, "krislet:5", null, null),
                6000, 5, 1, 2, 0, null, new Evaluating.Server(null, null, 60, 9), null, 0, null, null,
                new Evaluating.GameLogs(teacher, imitator, team), null);
    }

    private Evaluating.Events events() {
        return new Evaluating.Events() {
            @Override
            public void learnt(int scenes, MatchConfig config) {
                told.add("learnt " + scenes + " scenes; " + config.describe());
            }

            @Override
            public void daggerBegins() {
                told.add("dagger begins");
            }

            @Override
            public void round(Dagger.Round round) {
                told.add("round " + round.number());
            }

            @Override
            public void figures(Evaluating.Outcome outcome) {
                told.add("figures, report " + outcome.report());
            }
        };
    }

    /** Teal (krislet) against {@code opponent}, 300 cycles a game, one .rcg and .rcl per seed in {@code directory}. */
    private static Path record(Path directory, String opponent, int... seeds) throws IOException {
        Files.createDirectories(directory);
        for (int seed : seeds) {
            Path game = directory.resolve("game" + seed);
            GameSetup setup = new GameSetup(new GameSetup.Team("Teal", 2, Teachers.byName("krislet")),
                    new GameSetup.Team(opponent, 2, Teachers.byName("krislet")), 300, seed, directory.resolve("players" + seed));
            Simulator simulator = new Simulator(setup).recordTo(game);
            simulator.run(cycle -> { });
            for (Path log : simulator.recorded()) {
                String name = log.getFileName().toString();
                Files.move(log, directory.resolve("game" + seed + name.substring(name.lastIndexOf('.'))));
            }
        }
        return directory;
    }

    /** The stages begun ("Task total"), the steps told and the stages not ended. */
    private static final class Recorded implements Progress {
        final List<String> begun = new ArrayList<>();
        final AtomicLong steps = new AtomicLong();
        int open;

        @Override
        public void begin(String task, long total) {
            begun.add(task + " " + total);
            open++;
        }

        @Override
        public void step() {
            steps.incrementAndGet();
        }

        @Override
        public void stepBy(long count) {
            steps.addAndGet(count);
        }

        @Override
        public void end() {
            open--;
        }
    }
}
