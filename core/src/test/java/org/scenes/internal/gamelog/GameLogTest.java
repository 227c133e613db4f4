package org.scenes.internal.gamelog;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Pattern;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Side;

class GameLogTest {
    private static final List<String> PARAMETERS = List.of("(server_param (goal_width 14.02))",
            "(player_param (player_types 1))", "(player_type (id 0)(player_speed_max 1.05))");

    // The show grammar of rcssserver's monitor protocol v3 text (src/monitor_protocol-v3.txt), with the
    // focus point and the twelfth count of log version 6, written here independently of the reader.
    private static final String REAL = "-?\\d+(\\.\\d+)?(e[+-]\\d\\d)?";
    private static final String PLAYER = "\\(\\((l|r) \\d{1,2}\\) \\d+ (0x[0-9a-f]+|0)( " + REAL + "){6}( " + REAL
            + " " + REAL + ")? \\(v [hl] " + REAL + "\\)( \\(fp " + REAL + " " + REAL + "\\))? \\(s( " + REAL
            + "){3,4}\\)( \\(f [lr] \\d+\\))? \\(c( \\d+){11,12}\\)\\)";
    private static final Pattern SHOW = Pattern.compile("\\(show \\d+ \\(\\(b\\)( " + REAL + "){4}\\)( " + PLAYER
            + ")*\\)");
    private static final Pattern PLAYMODE = Pattern.compile("\\(playmode \\d+ [a-z_]+\\)");
    private static final Pattern TEAM = Pattern.compile("\\(team \\d+ \\S+ \\S+ \\d+ \\d+( \\d+ \\d+ \\d+ \\d+)?\\)");
    private static final Pattern PARAMETER = Pattern.compile("\\((server_param|player_param|player_type) .*\\)");

    @TempDir
    Path dir;

    private static GameFrame frame(int time, String mode, int scoreLeft, Random random) {
        List<PlayerState> players = new ArrayList<>();
        for (Side side : Side.values()) {
            for (int unum = 1; unum <= 3; unum++) {
                boolean goalie = unum == 1;
                players.add(new PlayerState(side, unum, 0, PlayerState.STANDING | (goalie ? PlayerState.GOALIE : 0),
                        random.nextDouble() * 100 - 50, random.nextDouble() * 60 - 30, random.nextGaussian() * 0.3,
                        -0.00001, random.nextDouble() * 360 - 180, 30.5, unum == 2 ? 'l' : 'h', unum == 3 ? 180 : 90,
                        8000 - time, 0.8 + random.nextDouble() * 0.2, 1, Double.NaN,
                        new PlayerState.Counts(time, time * 2, 3, goalie ? 1 : 0, 1, 4, 2, 0, 0, 0, 0)));
            }
        }
        return new GameFrame(time, mode, "Teal", "Amber", scoreLeft, 0,
                new GameFrame.BallState(random.nextDouble() * 100 - 50, 1e-7, 2.123456789, -0.5), players);
    }

    private Path writeGame(Path file) throws IOException {
        Random random = new Random(5);
        try (GameLogWriter writer = GameLogWriter.create(file, PARAMETERS)) {
            writer.write(frame(0, "before_kick_off", 0, random)); // not recorded, as on the server
            writer.write(frame(0, "kick_off_l", 0, random));
            writer.write(frame(1, "play_on", 0, random));
            writer.write(frame(2, "play_on", 0, random));
            writer.write(frame(3, "goal_l_1", 1, random));
            writer.write(frame(3, "goal_l_1", 1, random));
            writer.write(frame(3, "kick_off_r", 1, random));
            writer.write(frame(4, "half_time", 1, random)); // the server's play mode is before_kick_off: not recorded
            writer.write(frame(5, "time_over", 1, random));
            writer.write(frame(5, "time_over", 1, random)); // only the first frame of time over
            writer.commit();
        }
        return file;
    }

    @Test
    void everyLineFollowsTheGrammarOfVersion6() throws IOException {
        List<String> lines = Files.readAllLines(writeGame(dir.resolve("game.rcg")));
        assertEquals("ULG6", lines.get(0));
        int shows = 0;
        for (String line : lines.subList(1, lines.size())) {
            if (line.startsWith("(show ")) {
                shows++;
                assertTrue(SHOW.matcher(line).matches(), line);
            } else {
                assertTrue(PLAYMODE.matcher(line).matches() || TEAM.matcher(line).matches()
                        || PARAMETER.matcher(line).matches(), line);
            }
        }
        assertEquals(7, shows);
        List<String> modes = lines.stream().filter(l -> l.startsWith("(playmode")).toList();
        assertEquals(List.of("(playmode 0 kick_off_l)", "(playmode 1 play_on)", "(playmode 3 goal_l)",
                "(playmode 3 kick_off_r)", "(playmode 5 time_over)"), modes);
        List<String> teams = lines.stream().filter(l -> l.startsWith("(team")).toList();
        // at the start, when the score changed, and the final line
        assertEquals(List.of("(team 0 Teal Amber 0 0)", "(team 3 Teal Amber 1 0)", "(team 5 Teal Amber 1 0)"), teams);
    }

    @Test
    void playersAreWrittenAsTheServerWritesThem() throws IOException {
        List<String> lines = Files.readAllLines(writeGame(dir.resolve("game.rcg")));
        String show = lines.stream().filter(l -> l.startsWith("(show 1 ")).findFirst().orElseThrow();
        // goalie flag 0x9, the velocity quantised to 0.0001 gives -0, low quality, wide view, no capacity
        assertTrue(show.contains(" ((l 1) 0 0x9 "), show);
        assertTrue(show.contains(" -0 ") , show);
        assertTrue(show.contains("30.5 (v h 90) (fp 0 0) (s 7999 "), show);
        assertTrue(show.contains("(v l 90)") && show.contains("(v h 180)"), show);
        assertTrue(show.contains(" 1 -1) (c 1 2 3 1 1 4 2 0 0 0 0 0))"), show);
        // the ball: y of 1e-7 quantised to 0, velocity to four decimals
        assertTrue(Pattern.compile("\\(\\(b\\) \\S+ 0 2\\.1235 -0\\.5\\)").matcher(show).find(), show);
    }

    @Test
    void everyShowHoldsAllTwentyTwoSlotsAndEmptyOnesAreDisabled() throws IOException {
        Path file = writeGame(dir.resolve("slots.rcg"));
        String show = Files.readAllLines(file).stream().filter(l -> l.startsWith("(show 1 ")).findFirst().orElseThrow();
        for (char side : new char[] {'l', 'r'}) {
            for (int unum = 1; unum <= 11; unum++) {
                assertTrue(show.contains(" ((" + side + " " + unum + ") "), side + " " + unum + ": " + show);
            }
        }
        // the game has 3 a side: the other slots are written with state 0, in order after them
        assertTrue(show.contains(" ((l 4) 0 0 0 0 0 0 0 0 (v h 90)"), show);
        assertTrue(show.indexOf("((l 11)") < show.indexOf("((r 1)"), show);
        // and reading leaves them out
        assertEquals(6, GameLogReader.readAll(file).get(1).players().size());
    }

    @Test
    void numbersAsACppStreamPrintsThem() {
        assertEquals("0.0001", LogNumbers.format(LogNumbers.quantize(0.00012, 0.0001)));
        assertEquals("-0", LogNumbers.format(LogNumbers.quantize(-0.00001, 0.0001)));
        assertEquals("130600", LogNumbers.format(130600));
        assertEquals("1e+06", LogNumbers.format(1e6));
        assertEquals("1.23457e+06", LogNumbers.format(1234567));
        assertEquals("1e-05", LogNumbers.format(0.00001));
        assertEquals("-12.3457", LogNumbers.format(-12.345678));
        assertEquals("0.94", LogNumbers.format(0.94));
        assertEquals("179.999", LogNumbers.format(LogNumbers.quantize(179.99901, 0.001)));
    }

    @Test
    void theReaderReadsWhatTheWriterWrote() throws IOException {
        List<GameFrame> frames = GameLogReader.readAll(writeGame(dir.resolve("game.rcg.gz")));
        assertEquals(7, frames.size());
        assertEquals(List.of("kick_off_l", "play_on", "play_on", "goal_l", "goal_l", "kick_off_r", "time_over"),
                frames.stream().map(GameFrame::playMode).toList());
        Random random = new Random(5);
        frame(0, "before_kick_off", 0, random);
        frame(0, "kick_off_l", 0, random);
        GameFrame written = frame(1, "play_on", 0, random);
        GameFrame read = frames.get(1);
        assertEquals(1, read.time());
        assertEquals("Teal", read.leftTeam());
        assertEquals(6, read.players().size());
        for (int i = 0; i < 6; i++) {
            PlayerState w = written.players().get(i);
            PlayerState r = read.players().get(i);
            assertEquals(w.side(), r.side());
            assertEquals(w.unum(), r.unum());
            assertEquals(w.state(), r.state());
            assertEquals(w.x(), r.x(), 5e-5);
            assertEquals(w.vx(), r.vx(), 5e-5);
            assertEquals(w.body(), r.body(), 5e-4);
            assertEquals(w.viewQuality(), r.viewQuality());
            assertEquals(w.viewWidth(), r.viewWidth());
            assertEquals(w.effort(), r.effort(), 1e-5);
            assertTrue(Double.isNaN(r.capacity()));
            assertEquals(w.counts(), r.counts());
        }
        assertEquals(1, frames.get(3).scoreLeft());
    }

    @Test
    void readsVersion4And5TextAndMonitorShows() throws IOException {
        Path file = dir.resolve("old.rcg");
        Files.writeString(file, String.join("\n", "ULG4",
                "(server_param (goal_width 14.02))",
                "(playmode 0 kick_off_l)",
                "(team 0 Alpha null 0 0)",
                "(msg 0 1 \"(referee kick_off_l)\")",
                "(show 0 ((b) 0 0 0 0) ((l 1) 0 0x9 -50 0 0 0 0 0 (v h 90) (s 8000 1 1) (f l 2) (c 0 0 0 0 1 0 0 0 0 0 0))"
                        + " ((l 2) 0 0x1 -10 -37 0 0 0 0 -3 4 (v l 180) (s 8000 1 1) (c 0 0 0 0 0 0 0 0 0 0 0))"
                        // a disabled slot (state 0): no one in the game, so not a player of the frame
                        + " ((l 3) 0 0 0 0 0 0 0 0 (v h 90) (s 8000 1 1) (c 0 0 0 0 0 0 0 0 0 0 0)))",
                "(show 1 (pm 3) (tm Alpha Beta 1 2) ((b) 1.5 -2 0.1 0)"
                        + " ((r 7) 3 0x1 10 5 0.5 -0.5 90 -45 (v h 60) (s 7000.5 0.9 0.8 130000) (c 1 2 3 0 1 0 0 0 0 0 0)))",
                ""));
        List<GameFrame> frames = GameLogReader.readAll(file);
        assertEquals(2, frames.size());
        GameFrame first = frames.get(0);
        assertEquals("kick_off_l", first.playMode());
        assertEquals("", first.rightTeam());
        assertEquals(PlayerState.STANDING | PlayerState.GOALIE, first.players().get(0).state());
        assertEquals(2, first.players().size());
        assertEquals(PlayerState.STANDING, first.players().get(1).state());
        assertEquals('l', first.players().get(1).viewQuality());
        GameFrame second = frames.get(1);
        assertEquals("play_on", second.playMode());
        assertEquals("Beta", second.rightTeam());
        assertEquals(2, second.scoreRight());
        PlayerState seven = second.players().get(0);
        assertEquals(Side.RIGHT, seven.side());
        assertEquals(3, seven.type());
        assertEquals(-45, seven.neck());
        assertEquals(130000, seven.capacity());
        assertEquals(new PlayerState.Counts(1, 2, 3, 0, 1, 0, 0, 0, 0, 0, 0), seven.counts());
    }

    @Test
    void readsTheJsonGameLog() throws IOException {
        Path file = dir.resolve("game.rcg.gz");
        String json = "[\n{\"version\":\"19.0.0\"},\n{\"timestamp\":\"2026-12-01T20:00:00+0000\"},\n"
                + "{\"server_param\":{\"goal_width\":14.02,\"visible_angle\":60,\"synch_see_offset\":0.0001,"
                + "\"fullstate_l\":false,\"landmark_file\":\"~/.rcssserver-landmark.xml\"}},\n"
                + "{\"player_param\":{\"player_types\":18}},\n"
                + "{\"player_type\":{\"id\":3,\"player_speed_max\":1.05,\"unum_far_length\":20}},\n"
                + "{\"playmode\":{\"time\":0,\"mode\":\"kick_off_l\"}},\n"
                + "{\"team\":{\"time\":0,\"l\":{\"name\":\"Alpha\",\"score\":0},\"r\":{\"name\":null,\"score\":0}}},\n"
                + "{\"show\":{\"time\":0,\"stime\":3,\"ball\":{\"x\":1,\"y\":2,\"vx\":0,\"vy\":-0.5},\"players\":["
                + "{\"side\":\"l\",\"unum\":1,\"type\":0,\"state\":9,\"x\":-50,\"y\":0,\"vx\":0,\"vy\":0,\"body\":10,"
                + "\"neck\":-20,\"vq\":\"h\",\"vw\":90,\"stamina\":8000,\"effort\":1,\"recovery\":1,\"capacity\":130600,"
                + "\"kick\":1,\"dash\":2,\"turn\":3,\"catch\":4,\"move\":5,\"turn_neck\":6,\"change_view\":7,\"say\":8,"
                + "\"tackle\":9,\"pointto\":10,\"attentionto\":11,\"change_focus\":12}]}}\n]\n";
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(file))) {
            out.write(json.getBytes(StandardCharsets.UTF_8));
        }
        List<GameFrame> frames = new ArrayList<>();
        List<String> parameters = new ArrayList<>();
        GameLogReader.forEach(file, frames::add, parameters::add);
        // the parameters as the text form writes them, for the same parser
        assertEquals(List.of("(server_param (goal_width 14.02) (visible_angle 60) (synch_see_offset 0.0001)"
                + " (fullstate_l 0) (landmark_file \"~/.rcssserver-landmark.xml\"))",
                "(player_param (player_types 18))", "(player_type (id 3) (player_speed_max 1.05) (unum_far_length 20))"),
                parameters);
        org.scenes.internal.protocol.Parameters server = (org.scenes.internal.protocol.Parameters) new org.scenes.internal.protocol.MessageParser()
                .parse(parameters.get(0));
        assertEquals(60, server.number("visible_angle"));
        assertEquals(1e-4, server.number("synch_see_offset"));
        assertEquals(1, frames.size());
        GameFrame frame = frames.get(0);
        assertEquals("kick_off_l", frame.playMode());
        assertEquals("Alpha", frame.leftTeam());
        assertEquals("", frame.rightTeam());
        assertEquals(-0.5, frame.ball().vy());
        PlayerState p = frame.players().get(0);
        assertEquals(9, p.state());
        assertEquals(-20, p.neck());
        assertEquals(new PlayerState.Counts(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11), p.counts());
    }

    @Test
    void errorsNameTheFileAndTheLine() throws IOException {
        Path file = dir.resolve("bad.rcg");
        Files.writeString(file, "ULG5\n(playmode 0 play_on)\n(show 1 ((b) 0 0 0 0) ((l 1) 0 0x1 1 2 3)\n");
        GameLogException e = assertThrows(GameLogException.class, () -> GameLogReader.readAll(file));
        assertEquals(3, e.line());
        assertTrue(e.getMessage().startsWith(file + ":3: "), e.getMessage());

        Files.writeString(file, "ULG6\n(show 1 ((b) 0 0 0 0)\n");
        e = assertThrows(GameLogException.class, () -> GameLogReader.readAll(file));
        assertTrue(e.getMessage().contains(":2: unbalanced"), e.getMessage());
        assertTrue(e.cutOff(), "a list left open is where the log was cut");

        Files.writeString(file, "ULG3\n");
        e = assertThrows(GameLogException.class, () -> GameLogReader.readAll(file));
        assertTrue(e.getMessage().contains(":1: not a text game log"), e.getMessage());
        assertFalse(e.cutOff());

        Files.writeString(file, "[\n{\"show\":{\"time\":1,\"ball\":{\"x\":1},\"players\":[]}}\n]\n");
        e = assertThrows(GameLogException.class, () -> GameLogReader.readAll(file));
        assertEquals(2, e.line());
        assertFalse(e.cutOff());
    }

    @Test
    void framesStreamOneAtATime() throws IOException {
        Path file = writeGame(dir.resolve("game.rcg"));
        List<Integer> times = new ArrayList<>();
        GameLogReader.forEach(file, frame -> times.add(frame.time()));
        assertEquals(List.of(0, 1, 2, 3, 3, 3, 5), times);
        assertFalse(Files.list(dir).anyMatch(p -> p.getFileName().toString().endsWith(".tmp")));
    }

    @Test
    void commandLogLines() throws IOException {
        Path file = dir.resolve("game.rcl");
        try (CommandLogWriter writer = CommandLogWriter.create(file)) {
            writer.received(0, 0, "Teal", 1, "(init Teal (version 9))");
            writer.referee(0, 30, "kick_off_l");
            writer.received(12, 0, "Amber", 11, "(dash 100)\0\0");
            writer.commit();
        }
        assertEquals(List.of("0,0\tRecv Teal_1: (init Teal (version 9))", "0,30\t(referee kick_off_l)",
                "12,0\tRecv Amber_11: (dash 100)"), Files.readAllLines(file));
    }

    /** The entries of a command log as TIME,STOPPAGE SENDER TEXT, or the error's message. */
    private List<String> entries(String... lines) throws IOException {
        Path file = dir.resolve("read.rcl");
        Files.write(file, List.of(lines));
        List<String> read = new ArrayList<>();
        try (CommandLogReader reader = CommandLogReader.open(file)) {
            for (CommandLogReader.Entry e = reader.next(); e != null; e = reader.next()) {
                read.add(e.time() + "," + e.stoppage() + " " + (e.referee() ? "referee" : e.team() + e.unum()) + " "
                        + e.text());
            }
        } catch (GameLogException e) {
            read.add(e.getMessage());
        }
        return read;
    }

    @Test
    void refereeCallsStampedACycleAheadOfTheBreaksPlacementsReadAtTheirStep() throws IOException {
        // rcssserver 19, a half ending on the step after a goal's kick-off (a HELIOS base game of 2026-12-07)
        assertEquals(List.of("1500,0 A6 (turn 60)", "1500,0 referee half_time", "1500,0 referee before_kick_off",
                "1500,0 B9 (move -1 -12)", "1501,0 B2 (dash 100)"), entries(
                "1500,0\tRecv A_6: (turn 60)", "1500,0\tRecv B_Coach: (done)", "1501,0\t(referee half_time)",
                "1501,0\t(referee before_kick_off)", "1500,0\tRecv B_9: (move -1 -12)", "1501,0\tRecv B_2: (dash 100)"));
        // as in every other game's log, calls at the players' step are read as they stand
        assertEquals(List.of("1500,0 referee half_time", "1500,0 A6 (move -25 0)"), entries(
                "1500,0\t(referee half_time)", "1500,0\tRecv A_6: (move -25 0)"));
        // out of order otherwise: two cycles ahead, or a player's line going back
        List<String> twoAhead = entries("1500,0\tRecv A_6: (turn 60)", "1502,0\t(referee half_time)",
                "1500,0\tRecv A_6: (move -25 0)");
        assertTrue(twoAhead.get(twoAhead.size() - 1).endsWith(":3: cycle 1500,0 comes after 1502,0: the command log is"
                + " out of order"), twoAhead.toString());
        List<String> calls = entries("1500,0\tRecv A_6: (turn 60)", "1501,0\t(referee half_time)",
                "1500,0\t(referee before_kick_off)");
        assertTrue(calls.get(calls.size() - 1).endsWith(":3: cycle 1500,0 comes after 1501,0: the command log is out"
                + " of order"), calls.toString());
        List<String> back = entries("1501,0\tRecv A_6: (turn 60)", "1500,0\tRecv A_6: (move -25 0)");
        assertTrue(back.get(back.size() - 1).endsWith(":2: cycle 1500,0 comes after 1501,0: the command log is out of"
                + " order"), back.toString());
    }
}
