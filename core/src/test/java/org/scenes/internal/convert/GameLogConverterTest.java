package org.scenes.internal.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.IntPredicate;
import java.util.function.IntUnaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandLogWriter;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogException;
import org.scenes.internal.gamelog.GameLogWriter;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.gamelog.ServerLogs;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.vision.VisionNumbers;

class GameLogConverterTest {
    private static final int FRAMES = 300;
    private static final String LEFT = "Red_A";
    private static final String RIGHT = "Blue";

    @TempDir
    Path dir;

    /** A game of two players a side: every player dashes in even cycles, as the counts of the shows say. */
    private Path gameLog() throws IOException {
        Path file = dir.resolve("game.rcg");
        try (GameLogWriter writer = GameLogWriter.create(file, List.of("(server_param (visible_angle 90)"
                + "(visible_distance 3)(quantize_step 0.1)(quantize_step_l 0.01)(send_step 150)(simulator_step 100))"))) {
            for (int time = 0; time < FRAMES; time++) {
                writer.write(frame(time));
            }
            writer.commit();
        }
        return file;
    }

    private static GameFrame frame(int time) {
        return frame(time, time == 0 ? "kick_off_l" : "play_on");
    }

    private static GameFrame frame(int time, String mode) {
        return frame(time, mode, (time + 1) / 2);
    }

    /** Every player's show with {@code dashes} executed. */
    private static GameFrame frame(int time, String mode, int dashes) {
        return frame(time, mode, dashes, 90);
    }

    /** Every player's show with {@code dashes} executed and a view width of {@code viewWidth} degrees. */
    private static GameFrame frame(int time, String mode, int dashes, double viewWidth) {
        List<PlayerState> players = new ArrayList<>();
        for (Side side : Side.values()) {
            for (int unum = 1; unum <= 2; unum++) {
                double x = (side == Side.LEFT ? -10 : 10) * unum;
                double body = side == Side.LEFT ? 0 : 180;
                players.add(new PlayerState(side, unum, 0, PlayerState.STANDING, x, unum * 2 - 3, 0, 0, body, 0,
                        'h', viewWidth, 8000, 1, 1, Double.NaN,
                        new PlayerState.Counts(0, dashes, 0, 0, 0, 0, 0, 0, 0, 0, 0)));
            }
        }
        return new GameFrame(time, mode, LEFT, RIGHT, 0, 0,
                new GameFrame.BallState(0.01 * time, 0, 0.01, 0), players);
    }

    private Path commandLog(String left, int firstCycle) throws IOException {
        return commandLog(left, firstCycle, 9);
    }

    private Path commandLog(String left, int firstCycle, int version) throws IOException {
        Path file = dir.resolve("game.rcl");
        try (CommandLogWriter writer = CommandLogWriter.create(file)) {
            for (String team : List.of(left, RIGHT)) {
                for (int unum = 1; unum <= 2; unum++) {
                    writer.received(0, 0, team, unum, "(init " + team + " (version " + version + "))");
                }
            }
            writer.referee(0, 0, "kick_off_l");
            for (int time = firstCycle; time < FRAMES; time += 2) {
                for (String team : List.of(left, RIGHT)) {
                    for (int unum = 1; unum <= 2; unum++) {
                        writer.received(time, 0, team, unum, "(dash 50)");
                    }
                }
            }
            writer.commit();
        }
        return file;
    }

    private static Map<String, List<Scene>> convert(Path game, Path commands, int threads) throws IOException {
        Map<String, List<Scene>> scenes = new TreeMap<>();
        GameLogConverter.Result result = new GameLogConverter(Grid.DEFAULT,
                Pairing.AUTO, Fading.HALFWAY, GameLogConverter.everyone(), threads).convert(game, commands,
                observer -> {
                    List<Scene> list = new ArrayList<>();
                    scenes.put(observer.team() + "_" + observer.uniformNumber(), list);
                    return list::add;
                });
        assertEquals(FRAMES, result.frames());
        return scenes;
    }

    @Test
    void everyPlayerGetsScenesOfItsRebuiltSees() throws IOException {
        Map<String, List<Scene>> scenes = convert(gameLog(), commandLog(LEFT, 0), 1);
        assertEquals(List.of("Blue_1", "Blue_2", "Red_A_1", "Red_A_2"), List.copyOf(scenes.keySet()));
        for (List<Scene> list : scenes.values()) {
            // a see 2 cycles in 3, a dash every other cycle: a scene for each see followed by a dash
            assertTrue(list.size() > FRAMES / 3, "scenes " + list.size());
            assertTrue(list.stream().allMatch(s -> s.actionType() == ActionType.DASH));
        }
        Scene first = scenes.get("Red_A_1").get(0);
        assertEquals(LEFT, first.observer().team());
        assertEquals(Side.LEFT, first.observer().side());
        SeenObject ball = first.objects().stream().filter(o -> o.kind() == ObjectKind.BALL).findFirst().orElseThrow();
        double distance = Math.hypot(0.01 * first.cycle() + 10, 1);
        assertEquals(VisionNumbers.seenDistance(distance, 0.1), ball.distance(), 1e-9);
        assertEquals(Math.rint(Math.toDegrees(Math.atan2(1, 0.01 * first.cycle() + 10))), ball.direction(), 1e-9);
        // the teammate 10 m behind is not in the cone, the opponents ahead are, with their team;
        // the number fades halfway between 20 and 40 m: shown at 20 m, not at 30.1 m
        List<SeenObject> players = first.objects().stream().filter(o -> o.kind() == ObjectKind.PLAYER).toList();
        assertEquals(2, players.size());
        assertTrue(players.stream().allMatch(p -> p.team().equals(RIGHT)));
        assertEquals(List.of(1, 0), players.stream().map(SeenObject::uniformNumber).toList());
    }

    @Test
    void clientsOfVersion18SeeSynchronouslyAndArePairedPerCycle() throws IOException {
        List<Scene> scenes = new ArrayList<>();
        GameLogConverter.Result result = new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY,
                GameLogConverter.only(RIGHT, 2), 1).convert(gameLog(), commandLog(LEFT, 0, 18),
                observer -> scenes::add);
        ConversionReport report = result.players().get(0).report();
        assertEquals(1, report.perCycleLogs());
        // a see every other step (synchronous, normal width); a dash every other cycle
        assertEquals(FRAMES / 2, report.sees(), 1);
        assertEquals(FRAMES / 2, scenes.size(), 1);
        // rcssserver's counter rises from the step after the init (0,0): sees in the even steps, as the dashes
        assertTrue(scenes.stream().allMatch(s -> s.seeAge() == 0 && s.cycle() % 2 == 0), "each dash on its see");
    }

    @Test
    void synchronousSeesFollowTheCounterThroughEveryChangeOfWidth() throws IOException {
        // the view width of each step: change_view wide at 5, narrow at 14, normal at 20, each from the next step
        IntUnaryOperator width = t -> t <= 5 ? 120 : t <= 14 ? 180 : t <= 20 ? 60 : 120;
        Path game = dir.resolve("game.rcg");
        try (GameLogWriter writer = GameLogWriter.create(game, List.of("(server_param (visible_angle 90)"
                + "(send_step 150)(simulator_step 100))"))) {
            for (int time = 0; time < 40; time++) {
                writer.write(frame(time, time == 0 ? "kick_off_l" : "play_on", (time + 1) / 2,
                        width.applyAsInt(time)));
            }
            writer.commit();
        }
        Path commands = dir.resolve("game.rcl");
        try (CommandLogWriter writer = CommandLogWriter.create(commands)) {
            writer.received(0, 0, RIGHT, 2, "(init " + RIGHT + " (version 18))");
            writer.referee(0, 0, "kick_off_l");
            for (int time = 0; time < 40; time++) {
                String view = time == 5 ? "(change_view wide)" : time == 14 ? "(change_view narrow)"
                        : time == 20 ? "(change_view normal)" : "";
                writer.received(time, 0, RIGHT, 2, (time % 2 == 0 ? "(dash 50)" : "(turn_neck 10)") + view);
            }
            writer.commit();
        }
        List<Scene> scenes = new ArrayList<>();
        new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY, GameLogConverter.only(RIGHT, 2), 1)
                .convert(game, commands, observer -> scenes::add);
        // the counter rises from step 1: normal (2) sees 2, 4; wide (3) counts on from 1: 7, 10, 13;
        // narrow (1) from 15 every step to 20; normal again from 21 (counter at 0): 22, 24, ...
        List<Integer> expected = new ArrayList<>(List.of(2, 4, 7, 10, 13, 15, 16, 17, 18, 19, 20));
        for (int time = 22; time < 40; time += 2) {
            expected.add(time);
        }
        assertEquals(expected, scenes.stream().filter(s -> s.seeAge() == 0).map(Scene::cycle).toList());
        assertEquals(38, scenes.size(), "a scene each cycle from the first see on");
    }

    @Test
    void theStepsBeforeAKickOffCountAlsoWhenThePlayModeIsTheSameOnBothSides() throws IOException {
        // a kick-off not taken by half time: kick_off_l before and after the 100 steps the game log skips
        int half = 150;
        Path game = dir.resolve("game.rcg");
        try (GameLogWriter writer = GameLogWriter.create(game, List.of("(server_param (send_step 150)"
                + "(simulator_step 100))"))) {
            for (int time = 0; time < FRAMES; time++) {
                if (time == half) {
                    writer.write(frame(time, "before_kick_off"));
                }
                writer.write(frame(time, time <= half ? "kick_off_l" : "play_on"));
            }
            writer.commit();
        }
        Path commands = dir.resolve("game.rcl");
        try (CommandLogWriter writer = CommandLogWriter.create(commands)) {
            writer.received(0, 0, LEFT, 1, "(init " + LEFT + " (version 9))");
            writer.referee(0, 0, "kick_off_l");
            for (int time = 0; time < FRAMES; time += 2) {
                if (time == half) {
                    writer.referee(time, 0, "half_time");
                    writer.referee(time, 0, "before_kick_off");
                    writer.referee(time, 100, "kick_off_l");
                }
                writer.received(time, time == half ? 100 : 0, LEFT, 1, "(dash 50)"); // as the shows count
            }
            writer.commit();
        }
        List<Scene> scenes = new ArrayList<>();
        new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY, GameLogConverter.only(LEFT, 1), 1)
                .convert(game, commands, observer -> scenes::add);
        // a see in the steps of 150 ms multiples: two steps in three; the 100 skipped steps shift
        // which cycles those are by one
        List<Integer> before = scenes.stream().map(Scene::cycle).filter(c -> c < half).toList();
        List<Integer> after = scenes.stream().map(Scene::cycle).filter(c -> c > half).toList();
        assertTrue(before.size() > half / 4 && after.size() > (FRAMES - half) / 4, before.size() + ", " + after.size());
        assertTrue(before.stream().allMatch(c -> c % 3 != 1), before.toString());
        assertTrue(after.stream().allMatch(c -> c % 3 != 0), after.toString());
    }

    @ParameterizedTest
    @ValueSource(ints = {0, 1, 2})
    void anAsynchronousPlayersSeePhaseIsInferredFromWhenItsCommandsCame(int seeless) throws IOException {
        // every player dashes in the cycles of its sees, which are those t mod 3 != seeless (a see
        // every 150 ms: two steps in three); the first step's clock gives t mod 3 != 1
        Path game = dir.resolve("game.rcg");
        try (GameLogWriter writer = GameLogWriter.create(game, List.of("(server_param (send_step 150)"
                + "(simulator_step 100))"))) {
            int dashes = 0;
            for (int time = 0; time < FRAMES; time++) {
                writer.write(frame(time, time == 0 ? "kick_off_l" : "play_on", dashes));
                dashes += time % 3 != seeless ? 1 : 0; // executed at the end of the cycle: in the next show
            }
            writer.commit();
        }
        Path commands = dir.resolve("game.rcl");
        try (CommandLogWriter writer = CommandLogWriter.create(commands)) {
            writer.referee(0, 0, "kick_off_l");
            for (int time = 0; time < FRAMES; time++) {
                for (String team : List.of(LEFT, RIGHT)) {
                    for (int unum = 1; unum <= 2 && time % 3 != seeless; unum++) {
                        writer.received(time, 0, team, unum, "(dash 50)");
                    }
                }
            }
            writer.commit();
        }
        for (GameLogConverter.SeePhase phase : GameLogConverter.SeePhase.values()) {
            List<Scene> scenes = new ArrayList<>();
            new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY, GameLogConverter.only(LEFT, 1), 1)
                    .seePhase(phase).convert(game, commands, observer -> scenes::add);
            List<Integer> cycles = scenes.stream().map(Scene::cycle).toList();
            int expected = phase == GameLogConverter.SeePhase.INFER ? seeless : 1;
            assertTrue(cycles.size() > FRAMES / 2, phase + ": " + cycles.size());
            assertTrue(cycles.stream().allMatch(c -> c % 3 != expected), phase + ": " + cycles);
        }
    }

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void rcssserversSeeClockStartsAtTheTickAfterTheInitAndRunsThroughTheHalfTimeBreak(boolean everyCycle)
            throws IOException {
        // as rcssserver logs it: players connect in step 26 of cycle 0, kick-off at 0,300; no show of
        // cycle 0 nor of the half-time break (150,0 to 150,19, its last step told by the players). The counter's first tick after step 26
        // (2625, 2662.5 or 2700 ms) puts the sees of the first half in the cycles t mod 3 != 2, != 1
        // or != 0; after 19 more steps, != 1, != 0, != 2. Dashing every cycle tells nothing, neither by
        // its timing nor by what it does (every see answered alike): the first tick; dashing in the
        // cycles t mod 3 != 1 tells the second.
        int half = 150;
        IntPredicate dashing = t -> t != half && (everyCycle || (t < half ? t % 3 != 1 : t % 3 != 0));
        Path game = dir.resolve("game.rcg");
        try (GameLogWriter writer = GameLogWriter.create(game, List.of("(server_param (send_step 150)"
                + "(simulator_step 100))"))) {
            int dashes = 0;
            for (int time = 1; time < FRAMES; time++) {
                if (time != half) {
                    writer.write(frame(time, time == 1 || time == half + 1 ? "kick_off_l" : "play_on", dashes));
                }
                dashes += dashing.test(time) ? 1 : 0;
            }
            writer.commit();
        }
        Path commands = dir.resolve("game.rcl");
        try (CommandLogWriter writer = CommandLogWriter.create(commands)) {
            for (String team : List.of(LEFT, RIGHT)) {
                for (int unum = 1; unum <= 2; unum++) {
                    writer.received(0, 26, team, unum, "(init " + team + " (version 9))");
                }
            }
            writer.referee(0, 300, "kick_off_l");
            for (int time = 1; time < FRAMES; time++) {
                if (time == half) {
                    writer.referee(time, 0, "half_time");
                    writer.referee(time, 0, "before_kick_off");
                    writer.referee(time, 19, "kick_off_l");
                    for (int unum = 1; unum <= 2; unum++) {
                        writer.received(time, 19, LEFT, unum, "(turn_neck 0)"); // the break's last step
                    }
                }
                for (String team : List.of(LEFT, RIGHT)) {
                    for (int unum = 1; unum <= 2 && dashing.test(time); unum++) {
                        writer.received(time, 0, team, unum, "(dash 50)");
                    }
                }
            }
            writer.commit();
        }
        List<Scene> scenes = new ArrayList<>();
        new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY, GameLogConverter.only(LEFT, 1), 1)
                .convert(game, commands, observer -> scenes::add);
        int seeless = everyCycle ? 2 : 1;
        List<Integer> first = scenes.stream().map(Scene::cycle).filter(c -> c < half).toList();
        List<Integer> second = scenes.stream().map(Scene::cycle).filter(c -> c > half + 1).toList();
        assertTrue(first.size() > half / 2 && second.size() > (FRAMES - half) / 2, first.size() + ", " + second.size());
        assertTrue(first.stream().allMatch(c -> c % 3 != seeless), first.toString());
        assertTrue(second.stream().allMatch(c -> c % 3 != (seeless + 2) % 3), second.toString());
    }

    @Test
    void threadsGiveTheSameScenes() throws IOException {
        Path game = gameLog();
        Path commands = commandLog(LEFT, 0);
        assertEquals(convert(game, commands, 1), convert(game, commands, 2));
    }

    @Test
    void aTruncatedGameLogWarnsAndKeepsTheScenesBefore() throws IOException {
        Path game = gameLog();
        List<String> lines = Files.readAllLines(game);
        int lastShow = lines.size() - 2; // the final (team ...) line follows the last show
        lines = new ArrayList<>(lines.subList(0, lastShow + 1));
        String cut = lines.get(lastShow);
        lines.set(lastShow, cut.substring(0, cut.length() / 2));
        Files.writeString(game, String.join("\n", lines), StandardCharsets.UTF_8);
        List<Scene> kept = new ArrayList<>();
        GameLogConverter.Result result = new GameLogConverter(Grid.DEFAULT, Pairing.AUTO, Fading.HALFWAY,
                GameLogConverter.only(LEFT, 1), 1).convert(game, commandLog(LEFT, 0), observer -> kept::add);
        assertEquals(FRAMES - 1, result.frames());
        assertEquals(1, result.warnings().size(), result.warnings().toString());
        assertTrue(result.warnings().get(0).startsWith(game + ":" + (lastShow + 1) + ": "), result.warnings().get(0));
        assertTrue(kept.size() > FRAMES / 3);
    }

    @Test
    void aCycleOutOfOrderNamesTheGameLogsLine() throws IOException {
        Path game = gameLog();
        List<String> lines = new ArrayList<>(Files.readAllLines(game));
        int show = lines.indexOf(lines.stream().filter(l -> l.startsWith("(show 100 ")).findFirst().orElseThrow());
        String moved = lines.remove(show - 10);
        lines.add(show, moved);
        Files.write(game, lines);
        GameLogException e = assertThrows(GameLogException.class, () -> convert(game, commandLog(LEFT, 0), 1));
        assertEquals(show + 1, e.line());
        assertTrue(e.getMessage().startsWith(game + ":" + (show + 1) + ": cycle "), e.getMessage());
        assertTrue(e.getMessage().contains("out of order"), e.getMessage());
    }

    @Test
    void aCommandLogOfOtherTeamsNamesItsLine() throws IOException {
        Path game = gameLog();
        Path commands = commandLog("Green", 0);
        LogException e = assertThrows(LogException.class, () -> convert(game, commands, 1));
        assertEquals(commands, e.file());
        assertEquals("Green_1", Files.readAllLines(commands).get((int) e.line() - 1).split("\t")[1]
                .substring(5, 12));
        assertTrue(e.getMessage().contains("neither team"), e.getMessage());
    }

    @Test
    void aCommandLogWhoseCyclesDisagreeIsRefused() throws IOException {
        Path game = gameLog();
        Path commands = commandLog(LEFT, 1); // dashes in odd cycles: the shows count them in even ones
        LogException e = assertThrows(LogException.class, () -> convert(game, commands, 2));
        assertEquals(commands, e.file());
        assertTrue(e.getMessage().contains("disagree"), e.getMessage());
    }

    @Test
    void aCommandLogOutOfOrderNamesItsLine() throws IOException {
        Path commands = dir.resolve("bad.rcl");
        Files.writeString(commands, "5,0\tRecv Red_A_1: (dash 50)\n4,0\tRecv Red_A_1: (dash 50)\n");
        GameLogException e = assertThrows(GameLogException.class, () -> convert(gameLog(), commands, 1));
        assertEquals(2, e.line());
        assertTrue(e.getMessage().startsWith(commands + ":2: "), e.getMessage());
    }

    @Test
    void commandLogLinesNameTeamsWithUnderscoresAndSkipCoaches() throws IOException {
        Path commands = dir.resolve("names.rcl");
        Files.writeString(commands, "0,3\tRecv HELIOS_A_11: (turn 0)(turn_neck 0)(done)\n"
                + "0,3\tRecv HELIOS_A_Coach: (eye on)\n1,0\t(referee play_on)\n");
        try (CommandLogReader reader = CommandLogReader.open(commands)) {
            CommandLogReader.Entry player = reader.next();
            assertEquals("HELIOS_A", player.team());
            assertEquals(11, player.unum());
            assertEquals(3, player.stoppage());
            assertEquals("(turn 0)(turn_neck 0)(done)", player.text());
            CommandLogReader.Entry referee = reader.next();
            assertTrue(referee.referee());
            assertEquals("play_on", referee.text());
            assertEquals(3, referee.line());
            assertNull(reader.next());
        }
    }

    @Test
    void serverLogsAreToldApartByContent() throws IOException {
        Path game = gameLog();
        Path renamed = Files.copy(game, dir.resolve("game.txt"));
        Path gzipped = dir.resolve("game.rcg.gz");
        try (var out = new java.util.zip.GZIPOutputStream(Files.newOutputStream(gzipped))) {
            out.write(Files.readAllBytes(game));
        }
        Path commands = commandLog(LEFT, 0);
        Path player = dir.resolve("player.lsf");
        Files.writeString(player, "(init Red_A (version 9))\n");
        assertEquals(ServerLogs.Kind.GAME, ServerLogs.detect(renamed));
        assertEquals(ServerLogs.Kind.GAME, ServerLogs.detect(gzipped));
        assertEquals(ServerLogs.Kind.COMMAND, ServerLogs.detect(commands));
        assertNull(ServerLogs.detect(player));
        assertNotNull(convert(gzipped, commands, 1));
    }
}
