package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.testing.Processes;

/**
 * {@code scenes evaluate --shadow-command}: the built-in teacher started as a program
 * ({@code java ... org.scenes.cli.Main team}) beside each imitating player in the embedded
 * simulator; its commands label DAgger's scenes as the teacher in process does. Two players, short games.
 */
@Tag("slow")
class EvaluateShadowCommandTest {
    @TempDir
    Path dir;

    /** The built-in teacher as a program: a JVM of this test's class path running {@code scenes team}. */
    private static String teamCommand(String marker) {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        return "'" + java + "' -cp '" + System.getProperty("java.class.path") + "' org.scenes.cli.Main team"
                + " --teacher krislet --server {host}:{port} --team {team} --players {players} --seed " + marker;
    }

    private static List<String> dagger(String... more) {
        List<String> args = new ArrayList<>(List.of("evaluate", "--metric", "ball-goal", "--players", "2",
                "--opponent", "krislet:2", "--cycles", "200", "--seeds", "1", "--train-games", "1", "--dagger", "1",
                "--json"));
        args.addAll(List.of(more));
        return args;
    }

    @Test
    void daggerWithAnExternalShadowLabelsAsTheTeacherInProcessDoes() throws Exception {
        CommandRunner external = new CommandRunner();
        Path parted = dir.resolve("parted.csv");
        int status = external.run(dagger("--shadow-command", teamCommand("7371"), "--disagreements",
                parted.toString()).toArray());
        assertEquals(ExitCodes.OK, status, external.err());
        JsonNode root = ConfigFiles.JSON.readTree(external.out());
        assertTrue(root.at("/about/shadow teacher").asText().startsWith("the command '"), root.get("about").toString());
        JsonNode rounds = root.get("rounds");
        int labelled = rounds.get(0).get("labelled").asInt();
        assertTrue(labelled > 50, "labelled " + labelled);
        assertEquals(rounds.get(0).get("scenes").asInt() + labelled, rounds.get(1).get("scenes").asInt());
        assertEquals(labelled, rounds.get(1).get("added").asInt());

        // round 0 as with the teacher in process: the same games, shadow decisions and partings
        CommandRunner inProcess = new CommandRunner();
        Path partedHere = dir.resolve("parted-here.csv");
        assertEquals(ExitCodes.OK, inProcess.run(dagger("--disagreements", partedHere.toString()).toArray()),
                inProcess.err());
        JsonNode here = ConfigFiles.JSON.readTree(inProcess.out()).at("/rounds/0");
        for (String figure : List.of("scenes", "agreement", "divergence", "ballDistance")) {
            assertEquals(here.get(figure), rounds.get(0).get(figure), figure);
        }
        // and the same labels but for the kick-off moves the program's runtime sends again after half time
        // (cycle 100), one scene of each player's: the teacher in process is fed, not run by a client
        assertEquals(here.get("labelled").asInt() + 2, labelled);
        List<String> lines = Files.readAllLines(parted);
        assertEquals("round,seed,unum,cycle,imitator,shadow", lines.get(0));
        assertEquals(Files.readAllLines(partedHere).stream().filter(l -> !l.startsWith("1,")).toList(),
                lines.stream().filter(l -> !l.startsWith("1,")).toList());
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("1,")), "round 1's partings too");
        Processes.assertNoneRunning("--seed 7371");
    }

    @Test
    void aShadowCommandThatFailsGivesOneLineAndLeavesNothingRunning() throws Exception {
        CommandRunner cli = new CommandRunner();
        assertEquals(ExitCodes.FAILURE, cli.run("evaluate", "--metric", "ball-goal", "--players", "1", "--opponent",
                "krislet:1", "--cycles", "50", "--seeds", "1", "--train-games", "1", "--shadow-command",
                "no-such-shadow-7372 {port}"));
        assertEquals(1, cli.err().strip().lines().count(), cli.err());
        assertTrue(cli.err().matches("scenes: Teal player 1's shadow: the command 'no-such-shadow-7372 \\d+' ended"
                + " \\(exit 127\\) before it sent its init \\(it said: .*command not found\\)\\s*"), cli.err());
        CommandRunner silent = new CommandRunner();
        assertEquals(ExitCodes.FAILURE, silent.run("evaluate", "--metric", "ball-goal", "--players", "1", "--opponent",
                "krislet:1", "--cycles", "50", "--seeds", "1", "--train-games", "1", "--server-wait", "1",
                "--shadow-command", "sleep 7373 # {port}"));
        assertEquals(1, silent.err().strip().lines().count(), silent.err());
        assertTrue(silent.err().matches("scenes: Teal player 1's shadow: the command 'sleep 7373 # \\d+' sent no init"
                + " to 127\\.0\\.0\\.1:\\d+ within 1 s\\s*"), silent.err());
        Processes.assertNoneRunning("sleep 7373");
        // a program that dies mid-game: ExternalShadowTest (its teacher program exits at a given cycle)
        Processes.assertNoneRunning("--seed 7373");
        CommandRunner usage = new CommandRunner();
        assertEquals(ExitCodes.USAGE, usage.run("evaluate", "--shadow-command", " "));
        assertTrue(usage.err().contains("--shadow-command: an empty command"), usage.err());
        assertEquals(ExitCodes.USAGE, usage.run("evaluate", "--shadow-command", "x", "--teacher-games", dir,
                "--imitator-games", dir));
        assertTrue(usage.err().contains("--shadow-command: a shadow plays beside the imitator's games"), usage.err());
    }

}
