package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class EvaluateCommandsTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    @Test
    void evaluateLearnsFromTheTeachersGamesAndReportsBothSides() throws Exception {
        Path report = dir.resolve("report");
        int status = cli.run("evaluate", "--metric", "ball-goal", "--players", "2", "--opponent", "krislet:2",
                "--cycles", "300", "--seeds", "2", "--train-games", "1", "--json", "--report", report);
        assertEquals(ExitCodes.OK, status, cli.err());
        JsonNode root = ConfigFiles.JSON.readTree(cli.out());
        assertEquals(2, root.get("seeds").size());
        double agreement = root.at("/figures/agreement/imitator/mean").asDouble();
        assertTrue(agreement > 0.5 && agreement <= 1, "agreement " + agreement);
        assertTrue(root.at("/figures/agreement/teacher/mean").isNull(), "no shadow beside the teacher");
        assertEquals(5, root.get("targets").size());
        assertTrue(root.at("/about/imitator learnt from").asText().startsWith("1 teacher games of 300 cycles"));
        String page = Files.readString(report.resolve("index.html"));
        assertEquals(2, count(page, "class=\"replay\""));
        assertTrue(page.contains("<svg"));
        assertTrue(!page.contains("src=\"http") && !page.contains("href=\"http") && !page.contains("@import"),
                "nothing fetched from the network");
    }

    @Test
    void evaluatePlaysOnAServerServingOneGameAfterAnother() throws Exception {
        int port;
        try (java.net.DatagramSocket probe = new java.net.DatagramSocket(0)) {
            port = probe.getLocalPort();
        }
        Path logs = Files.createDirectories(dir.resolve("logs"));
        CommandRunner server = new CommandRunner();
        int[] serverStatus = {-1};
        Thread serving = new Thread(() -> serverStatus[0] = server.run("server", "--port", port, "--synch", "--games", "2",
                "--games-per-seed", "2", "--seed", "7", "--cycles", "100", "--record", logs));
        serving.start();
        int status = cli.run("evaluate", "--server", "127.0.0.1:" + port, "--server-logs", logs, "--server-wait", "30",
                "--metric", "ball-goal", "--players", "1", "--opponent", "krislet:1", "--cycles", "100", "--seeds", "1",
                "--first-seed", "7", "--train-games", "1", "--json");
        serving.join(60_000);
        assertEquals(ExitCodes.OK, status, cli.err());
        assertEquals(ExitCodes.OK, serverStatus[0], server.err());
        assertTrue(server.out().contains("game 2 of 2") && server.out().contains("seed 7"), server.out());
        JsonNode root = ConfigFiles.JSON.readTree(cli.out());
        assertTrue(root.at("/about/played on").asText().contains("127.0.0.1:" + port), root.toString());
        assertTrue(root.at("/about/not measured").isMissingNode(), "positions from the game log: " + root.get("about"));
        double answered = root.at("/figures/answered/imitator/mean").asDouble();
        assertTrue(answered > 0.5 && answered <= 1, "sees answered " + answered);
    }

    @Test
    void evaluateOnAServerRefusesBadOptionsAndSaysWhenNoServerTakesTheGame() throws Exception {
        assertEquals(ExitCodes.USAGE, cli.run("evaluate", "--server", "localhost"));
        assertTrue(cli.err().contains("--server"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("evaluate", "--server-logs", dir));
        assertTrue(cli.err().contains("--server-logs: needs --server"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("evaluate", "--server", "localhost:6000", "--server-wait", "0"));
        assertEquals(ExitCodes.USAGE, new CommandRunner().run("evaluate", "--seeds", "0"));
        assertEquals(ExitCodes.USAGE, cli.run("server", "--games", "0"));
        int port;
        try (java.net.DatagramSocket probe = new java.net.DatagramSocket(0)) {
            port = probe.getLocalPort();
        }
        assertEquals(ExitCodes.FAILURE, cli.run("evaluate", "--server", "127.0.0.1:" + port, "--server-wait", "1",
                "--metric", "ball-goal", "--players", "1", "--opponent", "krislet:1", "--cycles", "100", "--seeds", "1",
                "--train-games", "1"));
        assertTrue(cli.err().contains("no game on 127.0.0.1:" + port + " accepted Teal within 1 s"), cli.err());
    }

    @Test
    void matchPlaysTwoTeachersAndReportsTheScore() {
        int status = cli.run("match", "--left", "krislet:2", "--right", "statebased:2", "--cycles", "300");
        assertEquals(ExitCodes.OK, status, cli.err());
        Matcher score = Pattern.compile("Score +Teal \\(krislet:2\\) (\\d+) : (\\d+) Amber \\(statebased:2\\)")
                .matcher(cli.out());
        assertTrue(score.find(), cli.out());
        assertTrue(cli.out().contains("kicks / 1000 cycles"), cli.out());
        CommandRunner bad = new CommandRunner();
        assertEquals(ExitCodes.USAGE, bad.run("match", "--left", "imitator:2", "--right", "krislet:2"));
        assertTrue(bad.err().contains("needs its scenes"), bad.err());
    }

    @Test
    void replayWritesAPageForAGameLog() throws Exception {
        assertEquals(ExitCodes.OK, cli.run("simulate", "--cycles", "200", "--teams", "krislet:2,krislet:2",
                "--out-dir", dir.resolve("logs"), "--record", dir.resolve("rec")), cli.err());
        Path log;
        try (var files = Files.list(dir.resolve("rec"))) {
            log = files.filter(f -> f.toString().endsWith(".rcg")).findFirst().orElseThrow();
        }
        CommandRunner replay = new CommandRunner();
        Path page = dir.resolve("game.html");
        assertEquals(ExitCodes.OK, replay.run("replay", log, "-o", page), replay.err());
        String html = Files.readString(page);
        assertTrue(html.contains("class=\"replay-data\""));
        assertTrue(html.contains("\"left\":\"Teal\""), "team names in the data");
        CommandRunner missing = new CommandRunner();
        assertEquals(ExitCodes.FAILURE, missing.run("replay", dir.resolve("none.rcg"), "-o", dir.resolve("x.html")));
    }

    @Test
    void evaluateReadsExistingGameLogsOfAnyTeam() throws Exception {
        // the teacher's games against Amber, the "imitator's" (another teacher) against Red, the
        // imitator on the right in its second game: Teal is the one team of all four
        Path teacher = dir.resolve("teacher");
        Path imitator = dir.resolve("imitator");
        record(teacher, "krislet:2,krislet:2", "Teal,Amber", 1);
        record(teacher, "krislet:2,krislet:2", "Teal,Amber", 2);
        record(imitator, "statebased:2,krislet:2", "Teal,Red", 1);
        record(imitator, "krislet:2,statebased:2", "Red,Teal", 2);
        try (var files = Files.list(teacher)) {
            // one game without its command log: its commands come from the .rcg's counters
            Files.delete(files.filter(f -> f.toString().endsWith(".rcl")).sorted().findFirst().orElseThrow());
        }
        Path report = dir.resolve("report");
        int status = cli.run("evaluate", "--teacher-games", teacher, "--imitator-games", imitator, "--json",
                "--report", report);
        assertEquals(ExitCodes.OK, status, cli.err());
        JsonNode root = ConfigFiles.JSON.readTree(cli.out());
        assertEquals("Teal", root.at("/about/team").asText());
        assertTrue(root.at("/about/teacher games").asText().contains("1 .rcl, the others' .rcg counters"),
                root.get("about").toString());
        double dash = root.at("/figures/executedDash/teacher/mean").asDouble();
        assertTrue(dash > 0.3 && dash < 1, "executed dash share " + dash);
        assertTrue(root.at("/figures/dashShare").isMissingNode(), "no traffic traced: no mix of sees answered");
        double onPitch = root.at("/figures/onPitch/imitator/mean").asDouble();
        assertTrue(onPitch > 0.5 && onPitch <= 1, "on pitch " + onPitch);
        assertTrue(root.at("/executedDivergence/mean").asDouble() >= 0);
        assertEquals(2, root.at("/positions/imitator").size(), "two players' mean positions");
        assertEquals("executed dash share", root.at("/turing/features/5").asText());
        String page = Files.readString(report.resolve("index.html"));
        assertEquals(2, count(page, "class=\"replay\""));
        assertTrue(page.contains("Imitator, player 2"), "a heat map per uniform number");

        // several teams in every game: the team must be named
        CommandRunner both = new CommandRunner();
        assertEquals(ExitCodes.USAGE, both.run("evaluate", "--teacher-games", teacher, "--imitator-games", teacher));
        assertTrue(both.err().contains("--team: more than one team plays in all 4 games")
                && both.err().contains("Teal (4 games), Amber (4 games)"), both.err());
        assertEquals(ExitCodes.USAGE, both.run("evaluate", "--teacher-games", teacher, "--imitator-games", imitator,
                "--team", "Amber"));
        assertTrue(both.err().contains("not of Amber"), both.err());
        // a bad directory: one line, usage
        CommandRunner bad = new CommandRunner();
        assertEquals(ExitCodes.USAGE, bad.run("evaluate", "--teacher-games", dir.resolve("none"), "--imitator-games",
                imitator));
        assertEquals("scenes: --teacher-games: " + dir.resolve("none") + " is not a directory", bad.err().strip());
        assertEquals(ExitCodes.USAGE, bad.run("evaluate", "--teacher-games", teacher));
        assertTrue(bad.err().contains("give both"), bad.err());
        // one imitator game against two of the teacher: the folds could not pair them
        Path single = dir.resolve("single");
        Files.createDirectories(single);
        try (var files = Files.list(imitator)) {
            for (Path log : files.filter(f -> f.getFileName().toString().startsWith("game1.")).toList()) {
                Files.copy(log, single.resolve(log.getFileName()));
            }
        }
        CommandRunner unequal = new CommandRunner();
        assertEquals(ExitCodes.USAGE, unequal.run("evaluate", "--teacher-games", teacher, "--imitator-games", single));
        assertTrue(unequal.err().contains("holds 2 game logs") && unequal.err().contains("give as many of each"),
                unequal.err());
    }

    private static void record(Path directory, String teams, String names, int seed) {
        CommandRunner simulate = new CommandRunner();
        Path game = directory.resolve("game" + seed);
        assertEquals(ExitCodes.OK, simulate.run("simulate", "--cycles", "300", "--teams", teams, "--names", names,
                "--seed", seed, "--out-dir", directory.resolve("players" + seed), "--record", game), simulate.err());
        try (var files = Files.list(game)) {
            // the game's logs in the side's directory, named by the game
            for (Path log : files.toList()) {
                String name = log.getFileName().toString();
                Files.move(log, directory.resolve("game" + seed + name.substring(name.lastIndexOf('.'))));
            }
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static int count(String text, String part) {
        int count = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
            count++;
        }
        return count;
    }
}
