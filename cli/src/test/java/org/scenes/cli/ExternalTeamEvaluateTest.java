package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.simulator.server.GameSeries;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import org.scenes.testing.Processes;

/**
 * {@code scenes evaluate --teacher-command}: the built-in teacher started as an external program
 * ({@code java ... org.scenes.cli.Main team}) on the project's server, measured from the server's
 * logs; commands that fail leave nothing running. Short games of two players a side.
 */
@Tag("slow")
class ExternalTeamEvaluateTest {
    @TempDir
    static Path shared;
    private static Path scenes;

    @TempDir
    Path dir;

    /** The imitator's scenes: a simulated game's two Teal players, converted. */
    @BeforeAll
    static void learnScenes() {
        CommandRunner cli = new CommandRunner();
        assertEquals(ExitCodes.OK, cli.run("simulate", "--cycles", "300", "--teams", "krislet:2,krislet:2",
                "--out-dir", shared.resolve("players")), cli.err());
        scenes = shared.resolve("scenes.json.gz");
        assertEquals(ExitCodes.OK, cli.run("convert", shared.resolve("players/Teal_1.lsf.gz"),
                shared.resolve("players/Teal_2.lsf.gz"), "-o", scenes), cli.err());
    }

    /** The built-in teacher as a program: a JVM of this test's class path running {@code scenes team}. */
    private static String teamCommand(String marker) {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        return "'" + java + "' -cp '" + System.getProperty("java.class.path") + "' org.scenes.cli.Main team"
                + " --teacher krislet --server {host}:{port} --team {team} --players {players} --seed " + marker;
    }

    @Test
    void anExternalTeacherOnTheProjectsServerIsMeasuredFromTheServersLogs() throws Exception {
        Path logs = Files.createDirectories(dir.resolve("logs"));
        try (Server server = new Server(logs, 2, 200)) {
            Path report = dir.resolve("report");
            CommandRunner cli = new CommandRunner();
            int status = cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", logs,
                    "--server-wait", "60", "--teacher-command", teamCommand("7351"), "--players", "2", "--opponent",
                    "krislet:2", "--cycles", "200", "--seeds", "1", "--metric", "ball-goal", scenes, "--json",
                    "--report", report);
            assertEquals(ExitCodes.OK, status, cli.err());
            assertEquals(2, server.served().size(), "the teacher's game and the imitator's");
            JsonNode root = ConfigFiles.JSON.readTree(cli.out());
            assertTrue(root.at("/about/teacher").asText().contains("the command '"), root.get("about").toString());
            double dash = root.at("/figures/executedDash/teacher/mean").asDouble();
            assertTrue(dash > 0.3 && dash < 1, "the external teacher's executed dash share " + dash);
            assertTrue(root.at("/figures/executedDash/imitator/mean").asDouble() > 0.3);
            assertTrue(root.at("/figures/agreement").isMissingNode(), "no shadow beside an external teacher");
            assertEquals("executed dash share", root.at("/turing/features/5").asText());
            String page = Files.readString(report.resolve("index.html"));
            assertTrue(page.contains("id=\"replay-teacher\"") && page.contains("id=\"replay-imitator\""));
        }
        Processes.assertNoneRunning("7351");
    }

    @Test
    void anExternalOpponentPlaysTheRightSideAgainstTheTracedTeams() throws Exception {
        Path logs = Files.createDirectories(dir.resolve("logs"));
        try (Server server = new Server(logs, 2, 100)) {
            CommandRunner cli = new CommandRunner();
            int status = cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", logs,
                    "--server-wait", "60", "--opponent-command", teamCommand("7355").replace("--teacher krislet", "--teacher statebased"),
                    "--players", "1", "--cycles", "100", "--seeds", "1", "--metric", "ball-goal", scenes, "--json");
            assertEquals(ExitCodes.OK, status, cli.err());
            assertEquals(2, server.served().size());
            JsonNode root = ConfigFiles.JSON.readTree(cli.out());
            assertTrue(root.at("/about/opponent").asText().startsWith("Amber, 1 players, the command '"));
            // our teams are traced (the shadow beside the imitator), and measured from the logs too
            assertTrue(root.at("/figures/agreement/imitator/mean").isNumber(), root.get("figures").toString());
            assertTrue(root.at("/figures/executedDash/teacher/mean").asDouble() > 0.2);
        }
        Processes.assertNoneRunning("7355");
    }

    @Test
    void anExternalTeacherAndAnExternalOpponentTogetherAreMeasuredFromTheServersLogs() throws Exception {
        Path logs = Files.createDirectories(dir.resolve("logs"));
        try (Server server = new Server(logs, 2, 150)) {
            CommandRunner cli = new CommandRunner();
            int status = cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", logs,
                    "--server-wait", "60", "--teacher-command", teamCommand("7361"), "--opponent-command",
                    teamCommand("7362").replace("--teacher krislet", "--teacher statebased"), "--players", "2",
                    "--cycles", "150", "--seeds", "1", "--metric", "ball-goal", scenes, "--json");
            assertEquals(ExitCodes.OK, status, cli.err());
            List<ServerResult> served = server.served();
            assertEquals(2, served.size(), "the teacher's game and the imitator's");
            // the teacher's command joined first in its game, as the imitator did in its own: both on the left
            for (ServerResult game : served) {
                String log = game.logs().stream().map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".rcg"))
                        .findFirst().orElseThrow();
                assertTrue(log.matches("\\d{3}-Teal_\\d+-vs-Amber_\\d+\\.rcg"), log);
            }
            JsonNode root = ConfigFiles.JSON.readTree(cli.out());
            assertTrue(root.at("/about/teacher").asText().contains("the command '"), root.get("about").toString());
            assertTrue(root.at("/about/opponent").asText().startsWith("Amber, 2 players, the command '"),
                    root.get("about").toString());
            for (String side : List.of("teacher", "imitator")) {
                double dash = root.at("/figures/executedDash/" + side + "/mean").asDouble();
                assertTrue(dash > 0.2 && dash < 1, side + "'s executed dash share " + dash);
                assertTrue(root.at("/figures/ballDistance/" + side + "/mean").asDouble() > 0
                        && root.at("/figures/bodyPerStep/" + side + "/mean").asDouble() > 0,
                        root.get("figures").toString());
            }
        }
        Processes.assertNoneRunning("--seed 7361");
        Processes.assertNoneRunning("--seed 7362");
    }

    @Test
    void twoExternalTeamsWhoseCommandFailsGiveOneLineAndLeaveNothingRunning() throws Exception {
        Path logs = Files.createDirectories(dir.resolve("logs"));
        try (Server server = new Server(logs, 1, 200)) {
            CommandRunner cli = new CommandRunner();
            int status = cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", logs,
                    "--server-wait", "60", "--teacher-command", teamCommand("7363"), "--opponent-command",
                    "echo no such team >&2; exit 3", "--players", "2", "--cycles", "200", "--seeds", "1", "--metric",
                    "ball-goal", scenes);
            assertEquals(ExitCodes.FAILURE, status, cli.err());
            assertTrue(cli.err().strip().endsWith("Amber: the command 'echo no such team >&2; exit 3' ended (exit 3)"
                    + " before the game began (it said: no such team)"), cli.err());
            assertEquals(1, cli.err().strip().lines().count(), cli.err());
        }
        Processes.assertNoneRunning("--seed 7363");
        try (Server server = new Server(logs, 1, 200)) {
            // a teacher whose players never join: the opponent's command is never started
            CommandRunner cli = new CommandRunner();
            int status = cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", logs,
                    "--server-wait", "2", "--teacher-command", "sleep 7364", "--opponent-command", teamCommand("7365"),
                    "--players", "2", "--cycles", "200", "--seeds", "1", "--metric", "ball-goal", scenes);
            assertEquals(ExitCodes.FAILURE, status, cli.err());
            assertTrue(cli.err().strip().endsWith("Teal: no player of the command 'sleep 7364' joined the game on"
                    + " 127.0.0.1:" + server.port + " within 2 s"), cli.err());
            assertEquals(1, cli.err().strip().lines().count(), cli.err());
        }
        Processes.assertNoneRunning("sleep 7364");
        Processes.assertNoneRunning("--seed 7365");
        try (Server server = new Server(logs, 1, 3000)) {
            // both teams play a while of a long game, then the opponent's player processes are killed
            CommandRunner cli = new CommandRunner();
            CompletableFuture<Integer> status = new CompletableFuture<>();
            Thread evaluating = new Thread(() -> status.complete(cli.run("evaluate", "--server", "127.0.0.1:"
                    + server.port, "--server-logs", logs, "--server-wait", "60", "--teacher-command",
                    teamCommand("7366"), "--opponent-command", teamCommand("7367"), "--players", "2", "--cycles",
                    "3000", "--seeds", "1", "--metric", "ball-goal", scenes)), "evaluate");
            evaluating.setDaemon(true);
            evaluating.start();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (server.time.get() < 50 && !status.isDone() && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            List<ProcessHandle> opponent = Processes.running("--seed 7367");
            assertTrue(server.time.get() >= 50 && !opponent.isEmpty(), "the game under way: cycle "
                    + server.time.get() + ", opponent " + opponent + ", " + cli.err());
            opponent.forEach(ProcessHandle::destroyForcibly);
            assertEquals(ExitCodes.FAILURE, status.get(60, TimeUnit.SECONDS), cli.err());
            assertTrue(cli.err().strip().matches("(?s).*Amber: the command '[^\\n]*--seed 7367' ended \\(exit \\d+\\)"
                    + " at cycle \\d+, before time over.*"), cli.err());
            assertEquals(1, cli.err().strip().lines().count(), cli.err());
        }
        Processes.assertNoneRunning("--seed 7366");
        Processes.assertNoneRunning("--seed 7367");
    }

    @Test
    void anImitationTeamWithRolesPlaysOnTheServerInTheProtocolVersionAsked() throws Exception {
        Path perPlayer = dir.resolve("per-player");
        CommandRunner convert = new CommandRunner();
        assertEquals(ExitCodes.OK, convert.run("convert", shared.resolve("players/Teal_1.lsf.gz"),
                shared.resolve("players/Teal_2.lsf.gz"), "--out-dir", perPlayer), convert.err());
        Path logs = Files.createDirectories(dir.resolve("logs"));
        try (Server server = new Server(logs, 2, 100)) {
            CommandRunner cli = new CommandRunner();
            int status = cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", logs,
                    "--players", "2", "--opponent", "krislet:2", "--cycles", "100", "--seeds", "1", "--metric",
                    "ball-goal", "--knowledge", "counterpart", "--version", "18", perPlayer.resolve("Teal_1.json.gz"),
                    perPlayer.resolve("Teal_2.json.gz"), "--json");
            assertEquals(ExitCodes.OK, status, cli.err());
            JsonNode root = ConfigFiles.JSON.readTree(cli.out());
            assertTrue(root.at("/about/roles").asText().startsWith("counterpart knowledge, 2 recorded players"),
                    root.get("about").toString());
            List<String> inits = new java.util.ArrayList<>();
            try (java.util.stream.Stream<Path> files = Files.list(logs)) {
                for (Path rcl : files.filter(f -> f.toString().endsWith(".rcl")).toList()) {
                    Files.readAllLines(rcl).stream().filter(l -> l.contains("(init Teal")).forEach(inits::add);
                }
            }
            assertEquals(4, inits.size(), "two players in each of two games: " + inits);
            assertTrue(inits.stream().allMatch(l -> l.contains("(version 18)")), inits.toString());
        }
        // DAgger beside an external teacher: its program as the shadow; the teacher's figures only the logs give
        Path daggerLogs = Files.createDirectories(dir.resolve("dagger-logs"));
        try (Server server = new Server(daggerLogs, 3, 100)) {
            CommandRunner cli = new CommandRunner();
            int status = cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", daggerLogs,
                    "--server-wait", "60", "--teacher-command", teamCommand("7356"), "--shadow-command",
                    teamCommand("7357").replace("{players}", "1"), "--players", "1", "--opponent", "krislet:1",
                    "--cycles", "100", "--seeds", "1", "--metric", "ball-goal", "--knowledge", "counterpart",
                    perPlayer.resolve("Teal_1.json.gz"), "--dagger", "1");
            assertEquals(ExitCodes.OK, status, cli.err());
            assertEquals(3, server.served().size(), "the teacher's game and two rounds of the imitator's");
            String teacherRow = cli.out().lines().filter(l -> l.startsWith("teacher ")).findFirst().orElseThrow();
            assertTrue(teacherRow.matches("teacher\\s+\\d+\\.\\d\\d\\s+-\\s+-\\s*"),
                    "goals from the logs; no stuck share or distance without the teacher's traces: " + teacherRow);
            String secondRound = cli.out().lines().filter(l -> l.startsWith("1 ")).findFirst().orElseThrow();
            // round, scenes, added, goals, mix JSD, stuck, to ball, agreement, Turing: the mix's divergence from the
            // executed commands of the logs, the agreement with the shadow program
            String[] cells = secondRound.trim().split("\\s+");
            assertTrue(cells[4].matches("\\d\\.\\d{4}") && cells[7].matches("\\d+\\.\\d%"), secondRound);
        }
        Processes.assertNoneRunning("7356");
        Processes.assertNoneRunning("7357");
        CommandRunner usage = new CommandRunner();
        assertEquals(ExitCodes.USAGE, usage.run("evaluate", "--knowledge", "counterpart"));
        assertTrue(usage.err().contains("--knowledge: roles come from the uniform numbers of scene files"),
                usage.err());
        assertEquals(ExitCodes.USAGE, usage.run("evaluate", "--server", "127.0.0.1:6000", "--version", "99", scenes));
        assertTrue(usage.err().contains("--version: protocol version must be 7 to 19, not 99"), usage.err());
    }

    @Test
    void aCommandThatFailsNeverJoinsOrDiesGivesOneLineAndLeavesNothingRunning() throws Exception {
        Path logs = Files.createDirectories(dir.resolve("logs"));
        try (Server server = new Server(logs, 1, 200)) {
            CommandRunner cli = new CommandRunner();
            assertEquals(ExitCodes.FAILURE, evaluate(cli, server, "echo no such team >&2; exit 3", "2000", "10"));
            assertTrue(cli.err().strip().endsWith("ended (exit 3) before the game began (it said: no such team)"),
                    cli.err());
            assertEquals(1, cli.err().strip().lines().count(), cli.err());
        }
        try (Server server = new Server(logs, 1, 200)) {
            CommandRunner cli = new CommandRunner();
            assertEquals(ExitCodes.FAILURE, evaluate(cli, server, "sleep 7352 & sleep 7353", "200", "2"));
            assertTrue(cli.err().contains("no player of the command 'sleep 7352 & sleep 7353' joined the game on"
                    + " 127.0.0.1:" + server.port + " within 2 s"), cli.err());
            Processes.assertNoneRunning("sleep 735");
        }
        try (Server server = new Server(logs, 1, 3000)) {
            // the team plays a while of a long game, then its player processes are killed
            CommandRunner cli = new CommandRunner();
            CompletableFuture<Integer> status = new CompletableFuture<>();
            Thread evaluating = new Thread(() -> status.complete(evaluate(cli, server, teamCommand("7354"), "3000",
                    "60")), "evaluate");
            evaluating.setDaemon(true);
            evaluating.start();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (server.time.get() < 50 && !status.isDone() && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            List<ProcessHandle> team = Processes.running("--seed 7354");
            assertTrue(server.time.get() >= 50 && !team.isEmpty(), "the game under way: cycle " + server.time.get()
                    + ", team " + team + ", " + cli.err());
            team.forEach(ProcessHandle::destroyForcibly);
            assertEquals(ExitCodes.FAILURE, status.get(60, TimeUnit.SECONDS), cli.err());
            assertTrue(cli.err().matches("(?s).*ended \\(exit \\d+\\) at cycle \\d+, before time over.*"), cli.err());
            Processes.assertNoneRunning("7354");
        }
        CommandRunner usage = new CommandRunner();
        assertEquals(ExitCodes.USAGE, usage.run("evaluate", "--server", "127.0.0.1:6000", "--teacher-command", "x",
                scenes));
        assertTrue(usage.err().contains("--teacher-command: an external team plays on a server and is measured from"
                + " its logs"), usage.err());
        assertEquals(ExitCodes.USAGE, usage.run("evaluate", "--server", "127.0.0.1:6000", "--server-logs", logs,
                "--teacher-command", "x"));
        assertTrue(usage.err().contains("give the SCENES"), usage.err());
    }

    private static int evaluate(CommandRunner cli, Server server, String command, String cycles, String wait) {
        return cli.run("evaluate", "--server", "127.0.0.1:" + server.port, "--server-logs", server.logs,
                "--server-wait", wait, "--teacher-command", command, "--players", "2", "--opponent", "krislet:2",
                "--cycles", cycles, "--seeds", "1", "--metric", "ball-goal", scenes);
    }


    /** The project's server on a free port, serving a series of games, stopped on close. */
    private static final class Server implements AutoCloseable {
        final Path logs;
        final int port;
        /** The game clock of the latest step. */
        final java.util.concurrent.atomic.AtomicInteger time = new java.util.concurrent.atomic.AtomicInteger();
        private final GameSeries series;
        private final ExecutorService executor = Executors.newSingleThreadExecutor();
        private final Future<List<ServerResult>> serving;

        Server(Path logs, int games, int cycles) throws Exception {
            this.logs = logs;
            ServerConfig config = ServerConfig.defaults().withPort(0).withSynch(true).withGame(cycles, 1)
                    .withRecordDirectory(logs).withTimings(Duration.ofSeconds(1), Duration.ofSeconds(5));
            series = new GameSeries(config, games, games, line -> { });
            CompletableFuture<Integer> started = new CompletableFuture<>();
            serving = executor.submit(() -> series.run(s -> started.complete(s[1]), result -> { },
                    frame -> time.set(frame.time())));
            port = started.get(30, TimeUnit.SECONDS);
        }

        List<ServerResult> served() throws Exception {
            return serving.get(60, TimeUnit.SECONDS);
        }

        @Override
        public void close() {
            series.stop();
            executor.shutdownNow();
        }
    }
}
