package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.ServerAddress;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.server.GameSeries;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import org.scenes.simulator.teacher.Teachers;
import org.scenes.testing.Processes;

/**
 * A shadow teacher that is a program: the built-in Krislet as a process of its own
 * ({@link TeacherProgram}) beside each imitating player, over UDP. Short games, two players.
 */
@Tag("slow")
class ExternalShadowTest {
    private static final GameSetup.Team AMBER = new GameSetup.Team("Amber", 2, Teachers.byName("krislet"));

    /** The teacher program in a JVM of this test's class path; {@code marker} finds its processes. */
    static String program(String teacher, int dieAt, String marker) {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        return "'" + java + "' -Dmarker=" + marker + " -cp '" + System.getProperty("java.class.path") + "' "
                + TeacherProgram.class.getName() + " {host} {port} {team} " + teacher + " " + dieAt;
    }

    @Test
    void theProgramsCommandsAreTheTeachersRepliesToTheImitatorsPercepts() throws Exception {
        ExternalShadow external = new ExternalShadow(program("krislet", Integer.MAX_VALUE, "7361"),
                ExternalShadow.Pacing.EACH_MESSAGE, Duration.ofSeconds(60));
        BrainFactory driver = Teachers.byName("statebased");
        BrainFactory krislet = Teachers.byName("krislet");
        List<PlayerTrace> inProcess = new ArrayList<>();
        List<PlayerTrace> outside = new ArrayList<>();
        List<List<String>> inProcessCommands = new ArrayList<>();
        BrainFactory teal = (team, random) -> {
            PlayerTrace a = new PlayerTrace(inProcess.size() + 1);
            PlayerTrace b = new PlayerTrace(outside.size() + 1);
            inProcess.add(a);
            outside.add(b);
            List<String> commands = new ArrayList<>();
            inProcessCommands.add(commands);
            Brain teacher = krislet.create(team, new Random(7));
            Brain recorded = (message, send) -> teacher.receive(message, command -> {
                commands.add(command);
                send.accept(command);
            });
            // the driver plays; beside it the teacher in process and the same teacher as a program
            return new TracedBrain(new TracedBrain(driver.create(team, random), recorded, a), external.create(team,
                    null), b);
        };
        GameSetup setup = new GameSetup(new GameSetup.Team("Teal", 2, teal), AMBER, 200, 5L, null);
        List<ExternalShadow.Player> players;
        try {
            new Simulator(setup).run(time -> { });
        } finally {
            players = external.players();
            external.endGame();
        }
        assertEquals(2, players.size());
        for (int player = 0; player < 2; player++) {
            // every command but the kick-off moves (random spots, and the runtime sends them again after goals)
            List<String> program = players.get(player).sent().stream().map(ExternalShadow.Sent::command)
                    .filter(c -> !c.startsWith("(move")).toList();
            List<String> teacher = inProcessCommands.get(player).stream().filter(c -> !c.startsWith("(move")).toList();
            assertTrue(teacher.size() > 40, "the teacher answered " + teacher.size() + " times");
            assertEquals(teacher, program, "player " + (player + 1));
            List<PlayerTrace.Decision> here = inProcess.get(player).decisions();
            List<PlayerTrace.Decision> there = outside.get(player).decisions();
            assertEquals(here.size(), there.size());
            for (int i = 0; i < here.size(); i++) {
                assertEquals(here.get(i).time(), there.get(i).time());
                assertEquals(here.get(i).shadow(), there.get(i).shadow(), "see " + i + " at " + here.get(i).time());
            }
            assertTrue(here.stream().filter(d -> d.shadow() != null).count() > 40);
        }
        Processes.assertNoneRunning("-Dmarker=7361");
    }

    @Test
    void anEvaluationsExternalShadowGivesAgreementAndIsEndedAfterEachGame() throws Exception {
        ExternalShadow external = new ExternalShadow(program("krislet", Integer.MAX_VALUE, "7362"),
                ExternalShadow.Pacing.EACH_MESSAGE, Duration.ofSeconds(60));
        GameSetup.Team teacher = new GameSetup.Team("Teal", 2, Teachers.byName("krislet"));
        // the teacher imitating itself: the program beside it agrees on every see
        Evaluation.Plan plan = new Evaluation.Plan(teacher, Teachers.byName("krislet"), AMBER, 120, List.of(3L))
                .withShadow(external);
        Evaluation.Results results = Evaluation.run(plan, Arena.embedded(), done -> { });
        GameFigures figures = GameFigures.of(results.imitator().get(0));
        assertEquals(1.0, figures.agreement(), 1e-12);
        assertTrue(results.imitator().get(0).traces().get(0).decisions().stream().filter(d -> d.shadow() != null)
                .count() > 20);
        assertTrue(external.players().isEmpty(), "ended after the game");
        Processes.assertNoneRunning("-Dmarker=7362");
    }

    @Test
    void onASynchronousServerTheProgramAnswersTheServersThink() throws Exception {
        ExternalShadow external = new ExternalShadow(program("krislet", Integer.MAX_VALUE, "7366"),
                ExternalShadow.Pacing.AS_THE_SERVER, Duration.ofSeconds(60));
        GameSetup.Team teacher = new GameSetup.Team("Teal", 2, Teachers.byName("krislet"));
        Evaluation.Plan plan = new Evaluation.Plan(teacher, Teachers.byName("krislet"), AMBER, 100, List.of(1L))
                .withShadow(external);
        ServerConfig config = ServerConfig.defaults().withPort(0).withSynch(true).withGame(100, 1)
                .withTimings(Duration.ofSeconds(1), Duration.ofSeconds(5));
        GameSeries series = new GameSeries(config, 2, 2, line -> { });
        CompletableFuture<Integer> port = new CompletableFuture<>();
        ExecutorService executor = Executors.newSingleThreadExecutor();
        Evaluation.Results results;
        try {
            Future<List<ServerResult>> serving = executor.submit(
                    () -> series.run(started -> port.complete(started[1]), result -> { }, frame -> { }));
            LiveArena arena = new LiveArena(ClientOptions.of(new ServerAddress("127.0.0.1", port.get(30,
                    TimeUnit.SECONDS)), "Teal").withTimeouts(Duration.ofSeconds(5), Duration.ofSeconds(10)), null,
                    Duration.ofSeconds(30), notice -> { });
            results = Evaluation.run(plan, arena, done -> { });
            assertEquals(2, serving.get(60, TimeUnit.SECONDS).size());
        } finally {
            series.stop();
            executor.shutdownNow();
        }
        // each program answered the server's (think) of every step (100 cycles and the pauses)
        assertTrue(external.dones() >= 2 * 100, "(done)s: " + external.dones());
        PlayedGame game = results.imitator().get(0);
        for (PlayerTrace trace : game.traces()) {
            // the cycle's commands come at the server's (think): Krislet's replies to a cycle's sense_body
            // count for that cycle's see here, for the see before in process
            long answered = trace.decisions().stream().filter(d -> d.shadow() != null).count();
            assertTrue(answered > 20, "the shadow answered " + answered + " sees");
        }
        double agreement = GameFigures.of(game).agreement();
        assertTrue(agreement > 0.8, "the teacher beside itself agrees on " + agreement);
        assertTrue(external.players().isEmpty(), "ended after the game");
        Processes.assertNoneRunning("-Dmarker=7366");
    }

    @Test
    void aProgramThatCannotStartSendsNoInitOrDiesFailsTheGameAndIsEnded() throws Exception {
        IOException missing = failure("no-such-program-7363 {host} {port}", Duration.ofSeconds(30));
        assertTrue(missing.getMessage().startsWith("Teal player 1's shadow: the command 'no-such-program-7363 127.0.0.1 ")
                && missing.getMessage().contains("' ended (exit 127) before it sent its init (it said: ")
                && missing.getMessage().endsWith("command not found)"), missing.getMessage());
        IOException silent = failure("sleep 7364; echo {port}", Duration.ofSeconds(1));
        assertTrue(silent.getMessage().matches("Teal player 1's shadow: the command 'sleep 7364; echo \\d+' sent no"
                + " init to 127\\.0\\.0\\.1:\\d+ within 1 s"), silent.getMessage());
        Processes.assertNoneRunning("sleep 7364");
        IOException dying = failure(program("krislet", 40, "7365"), Duration.ofSeconds(60));
        assertTrue(dying.getMessage().matches("Teal player 1's shadow: the command '.*' ended \\(exit 3\\) at cycle"
                + " 40, before time over \\(it said: dying at 40\\)"), dying.getMessage());
        Processes.assertNoneRunning("-Dmarker=7365");
    }

    private static IOException failure(String command, Duration wait) {
        ExternalShadow external = new ExternalShadow(command, ExternalShadow.Pacing.EACH_MESSAGE, wait);
        Evaluation.Plan plan = new Evaluation.Plan(new GameSetup.Team("Teal", 1, Teachers.byName("krislet")),
                Teachers.byName("statebased"), AMBER, 100, List.of(1L)).withShadow(external);
        IOException failed = assertThrows(IOException.class, () -> Evaluation.run(plan, Arena.embedded(), done -> { }));
        assertEquals(1, failed.getMessage().lines().count(), failed.getMessage());
        assertTrue(external.players().isEmpty(), "ended after the game");
        return failed;
    }

}
