package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Side;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.gamelog.CommandLogWriter;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogWriter;
import org.scenes.internal.gamelog.PlayerState;
import picocli.CommandLine;

/** {@code scenes convert GAME.rcg [GAME.rcl]} and {@code scenes compare} from the command line. */
class GameLogConvertCommandTest {
    @TempDir
    Path dir;

    private String out;
    private String err;

    private int run(Object... args) {
        CommandLine commandLine = ScenesCommand.commandLine();
        StringWriter errors = new StringWriter();
        StringWriter output = new StringWriter();
        commandLine.setErr(new PrintWriter(errors));
        commandLine.setOut(new PrintWriter(output));
        String[] text = new String[args.length];
        for (int i = 0; i < args.length; i++) {
            text[i] = args[i].toString();
        }
        int code = commandLine.execute(text);
        out = output.toString();
        err = errors.toString();
        return code;
    }

    /** A 200-cycle game of one player a side, both dashing every other cycle. */
    private Path game() throws IOException {
        Path rcg = dir.resolve("g.rcg");
        try (GameLogWriter writer = GameLogWriter.create(rcg, List.of())) {
            for (int time = 0; time < 200; time++) {
                List<PlayerState> players = new ArrayList<>();
                for (Side side : Side.values()) {
                    players.add(new PlayerState(side, 1, 0, PlayerState.STANDING, side == Side.LEFT ? -5 : 5, 0, 0, 0,
                            side == Side.LEFT ? 0 : 180, 0, 'h', 90, 8000, 1, 1, Double.NaN,
                            new PlayerState.Counts(0, (time + 1) / 2, 0, 0, 0, 0, 0, 0, 0, 0, 0)));
                }
                writer.write(new GameFrame(time, "play_on", "My_Team", "Other", 0, 0,
                        new GameFrame.BallState(0, 0, 0, 0), players));
            }
            writer.commit();
        }
        try (CommandLogWriter writer = CommandLogWriter.create(dir.resolve("g.rcl"))) {
            for (int time = 0; time < 200; time += 2) {
                writer.received(time, 0, "My_Team", 1, "(dash 40)");
                writer.received(time, 0, "Other", 1, "(dash 40)");
            }
            writer.commit();
        }
        return rcg;
    }

    @Test
    void convertsEveryPlayerFindingTheCommandLogBeside() throws IOException {
        Path rcg = game();
        assertEquals(0, run("convert", rcg, "--out-dir", dir.resolve("s")), err);
        assertTrue(Files.isRegularFile(dir.resolve("s/My_Team_1.json.gz")));
        assertTrue(Files.isRegularFile(dir.resolve("s/Other_1.json.gz")));
        assertTrue(out.contains("My_Team_1"), out);
        assertEquals(0, run("compare", dir.resolve("s"), dir.resolve("s")), err);
        assertTrue(out.contains("100.000 % same type"), out);
    }

    @Test
    void zstdCompressionWritesTheSameScenesUnderTheirOwnEndingAndOnlyForOutDir() throws IOException {
        Path rcg = game();
        assertEquals(0, run("convert", rcg, "--out-dir", dir.resolve("gzip")), err);
        assertEquals(0, run("convert", rcg, "--out-dir", dir.resolve("zstd"), "--compression", "zstd"), err);
        for (String player : List.of("My_Team_1", "Other_1")) {
            Path zstd = dir.resolve("zstd/" + player + ".json.zst");
            assertTrue(Files.isRegularFile(zstd), player);
            assertEquals(0x28, Files.readAllBytes(zstd)[0], "zstd's magic");
            try (InputStream a = Inputs.open(dir.resolve("gzip/" + player + ".json.gz"));
                 InputStream b = Inputs.open(zstd)) {
                assertArrayEquals(a.readAllBytes(), b.readAllBytes(), player);
            }
        }
        assertEquals(0, run("compare", dir.resolve("gzip"), dir.resolve("zstd")), err);
        assertTrue(out.contains("100.000 % same type"), out);

        assertEquals(2, run("convert", rcg, "-o", dir.resolve("one.json.gz"), "--team", "Other",
                "--compression", "zstd"));
        assertTrue(err.contains("--compression names the files of --out-dir"), err);
        assertEquals(2, run("convert", rcg, "--out-dir", dir.resolve("x"), "--compression", "xz"));
        assertTrue(err.contains("expected gzip, zstd or none, not 'xz'"), err);
    }

    @Test
    void compareOfTwoDirectoriesReportsEveryPlayerThenTheSum() throws IOException {
        Path rcg = game();
        assertEquals(0, run("convert", rcg, "--out-dir", dir.resolve("s")), err);
        assertEquals(0, run("compare", dir.resolve("s"), dir.resolve("s")), err);
        int myTeam = out.indexOf("File                       My_Team_1.json.gz");
        int other = out.indexOf("File                       Other_1.json.gz");
        int sum = out.indexOf("Files                      2 of the same name, summed");
        assertTrue(myTeam >= 0 && other > myTeam && sum > other, out);
        assertTrue(out.substring(other, sum).contains("Players                    Other 1"), out);
        assertEquals(3, out.split("100.000 % same type", -1).length - 1, out);
        assertEquals(0, run("compare", dir.resolve("s"), dir.resolve("s"), "--json"), err);
        com.fasterxml.jackson.databind.JsonNode json = new com.fasterxml.jackson.databind.ObjectMapper().readTree(out);
        assertEquals(2, json.get("players").size(), out);
        assertEquals("Other_1.json.gz", json.get("players").get(1).get("file").asText());
        assertEquals(json.get("paired").asLong(), json.get("players").get(0).get("paired").asLong()
                + json.get("players").get(1).get("paired").asLong(), out);
    }

    @Test
    void oneFileTakesOnePlayer() throws IOException {
        Path rcg = game();
        Path rcl = dir.resolve("g.rcl");
        assertEquals(2, run("convert", rcg, rcl, "-o", dir.resolve("all.json")));
        assertTrue(err.contains("-o takes the scenes of one player"), err);
        assertTrue(Files.notExists(dir.resolve("all.json")));
        assertEquals(0, run("convert", rcg, rcl, "-o", dir.resolve("one.json"), "--team", "Other"), err);
        assertTrue(Files.isRegularFile(dir.resolve("one.json")));
    }

    @Test
    void aCommandLogAloneOrMissingIsAUsageError() throws IOException {
        Path rcg = game();
        Path rcl = dir.resolve("g.rcl");
        assertEquals(2, run("convert", rcl, "--out-dir", dir.resolve("s")));
        assertTrue(err.contains("is a command log"), err);
        assertEquals(2, run("convert", rcg, rcl, "--commands", "infer", "--out-dir", dir.resolve("s")));
        assertTrue(err.contains("--commands infer takes the game log alone"), err);
        assertEquals(2, run("convert", rcg, "--commands", "guess", "--out-dir", dir.resolve("s")));
        assertTrue(err.contains("'--commands'") && err.contains("expected rcl, infer or auto, not 'guess'"), err);
        Files.delete(rcl);
        assertEquals(2, run("convert", rcg, "--commands", "rcl", "--out-dir", dir.resolve("s")));
        assertTrue(err.contains("no command log beside"), err);
    }

    @Test
    void aGameLogAloneHasItsCommandsInferred() throws IOException {
        Path rcg = game();
        Files.delete(dir.resolve("g.rcl"));
        assertEquals(0, run("convert", rcg, "--out-dir", dir.resolve("s")), err);
        assertTrue(out.contains("commands inferred from it"), out);
        assertTrue(Files.isRegularFile(dir.resolve("s/My_Team_1.json.gz")));
    }

    @Test
    void aBadLineOfTheGameLogIsFailedWorkNamingFileAndLine() throws IOException {
        Path rcg = game();
        List<String> lines = new ArrayList<>(Files.readAllLines(rcg));
        lines.add(10, "(frobnicate 1)");
        Files.write(rcg, lines);
        // a GameLogException, as a LogException of a player's log: the data is at fault, exit 1
        assertEquals(1, run("convert", rcg, "--out-dir", dir.resolve("s")));
        assertTrue(err.contains(rcg + ":11: unknown line '(frobnicate 1)'"), err);
        assertEquals(1, err.strip().lines().count(), err);
    }
}
