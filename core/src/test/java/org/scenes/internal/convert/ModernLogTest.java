package org.scenes.internal.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.internal.protocol.CommandType;

/**
 * Logs shaped like a librcsc (HELIOS base) player's on rcssserver 19, generated here: protocol 18,
 * {@code (ok synch_see)}, a sense_body every cycle and a see every other cycle, all of a cycle's
 * commands in one datagram with {@code turn_neck} every cycle and {@code (turn 0)} as "do nothing".
 */
class ModernLogTest {
    @TempDir
    Path dir;

    private final List<Scene> scenes = new ArrayList<>();
    private final List<MalformedLine> warnings = new ArrayList<>();

    /** The body command of cycle {@code t}: a dash with a direction, a no-op turn, a turn or a kick. */
    static String body(int t) {
        return switch (t % 4) {
            case 0 -> "(dash 76.345 60)";
            case 1 -> "(turn 0)";
            case 2 -> "(turn -35.5)";
            default -> "(kick 80.2 -10)";
        };
    }

    /** A proxy log of {@code cycles} cycles; {@code synch} false leaves out the server's (ok synch_see). */
    static List<String> proxyLog(int cycles, boolean synch) {
        List<String> lines = new ArrayList<>();
        lines.add("#scenes-proxy-log 1");
        lines.add("0.000 c2s (init HELIOS_base (version 18))");
        lines.add("0.001 s2c (init l 7 before_kick_off)");
        lines.add("0.002 s2c (server_param (goal_width 14.02)(synch_see_offset 0))");
        if (synch) {
            lines.add("0.003 c2s (synch_see)");
            lines.add("0.004 s2c (ok synch_see)");
        }
        lines.add("0.005 c2s (move -10 5)(done)");
        for (int t = 1; t <= cycles; t++) {
            String time = String.format(Locale.ROOT, "%d.%03d", t / 10, (t % 10) * 100);
            lines.add(time + " s2c (sense_body " + t + " (view_mode high normal) (stamina 8000 1 130600)"
                    + " (speed 0 0) (head_angle 0) (kick 0) (dash 0) (turn 0) (say 0) (turn_neck 0))");
            if (t % 2 == 1) {
                lines.add(time + " s2c (see " + t + " ((g r) 40 " + (t % 30) + ") ((b) " + (5 + t % 7) + " 3 0 0)"
                        + " ((p \"HELIOS_base\" 9) 12 -20))");
            }
            lines.add(time + " c2s " + body(t) + "(turn_neck " + (t % 3 == 0 ? 0 : 15) + ")(attentionto our 9)"
                    + "(say \"a(b)c\")(done)");
        }
        return lines;
    }

    private Path write(String name, List<String> lines) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, lines);
        return file;
    }

    private ConversionReport convert(Path file, Pairing pairing) throws IOException {
        return SceneConverter.with(Grid.DEFAULT).pairing(pairing).warnings(warnings::add).build().convert(file, scenes::add);
    }

    @Test
    void synchronousVisionGivesAScenePerCycleWithTheAgeOfItsSee() throws IOException {
        int cycles = 200;
        ConversionReport report = convert(write("helios.log", proxyLog(cycles, true)), Pairing.AUTO);
        assertEquals(List.of(), warnings);
        assertEquals(0, report.malformed());
        assertEquals(1, report.perCycleLogs());
        assertEquals(cycles, scenes.size(), "one scene per cycle");
        assertEquals(cycles, report.commands(CommandType.TURN_NECK));
        assertEquals(cycles, report.commands(CommandType.DONE) - 1, "and the move's (done)");
        assertEquals(cycles, report.commands(CommandType.SAY));
        long bodyCommands = report.commands(CommandType.DASH) + report.commands(CommandType.TURN)
                + report.commands(CommandType.KICK);
        assertEquals(cycles, bodyCommands);
        assertEquals(1, report.dropped(DropReason.NO_SEE), "the move before the first see");
        for (int i = 0; i < scenes.size(); i++) {
            Scene scene = scenes.get(i);
            int t = i + 1;
            assertEquals(t, scene.cycle());
            assertEquals(t % 2 == 1 ? 0 : 1, scene.seeAge(), "cycle " + t);
            assertEquals(2, scene.actions().size());
            assertEquals(body(t), scene.actions().get(0).command());
            assertEquals(Action.turnNeck(t % 3 == 0 ? 0 : 15), scene.actions().get(1));
        }
        assertEquals(Action.dash(76.345, 60), scenes.get(3).primaryAction());
        assertEquals(Long.valueOf(cycles / 2), report.seeAges().get(1));
    }

    @Test
    void everyBodyCommandIsKept() throws IOException {
        ConversionReport report = convert(write("helios.log", proxyLog(100, true)), Pairing.AUTO);
        long kicks = scenes.stream().filter(s -> s.primaryAction().type() == org.scenes.api.ActionType.KICK).count();
        assertEquals(report.commands(CommandType.KICK), kicks);
        assertEquals(0, report.extraActions());
    }

    @Test
    void perSeePairingOfTheSameTrafficKeepsOnlyTheCyclesWithASee() throws IOException {
        ConversionReport report = convert(write("helios.log", proxyLog(100, true)), Pairing.SEE);
        assertEquals(0, report.perCycleLogs());
        assertEquals(50, scenes.size());
        assertTrue(report.extraActions() > 0, "the cycles without a see become extra actions");
        assertTrue(scenes.stream().allMatch(s -> s.seeAge() == 0));
    }

    @Test
    void withoutSynchSeeAutoKeepsTheClassicRuleAndCycleCanBeAskedFor() throws IOException {
        convert(write("async.log", proxyLog(40, false)), Pairing.AUTO);
        assertEquals(20, scenes.size());
        scenes.clear();
        ConversionReport report = convert(write("async.log", proxyLog(40, false)), Pairing.CYCLE);
        assertEquals(40, scenes.size());
        assertEquals(1, report.perCycleLogs());
    }

    @Test
    void everyStepOfAStandingClockIsACycleOfItsOwn() throws IOException {
        List<String> lines = new ArrayList<>(List.of("#scenes-proxy-log 1", "0 c2s (init T (version 19))",
                "0 s2c (init r 2 before_kick_off)", "0 s2c (ok synch_see)"));
        for (int step = 0; step < 5; step++) {
            lines.add("0 s2c (sense_body 0 (view_mode high normal))");
            if (step == 0 || step == 3) {
                lines.add("0 s2c (see 0 ((b) 10 " + step + "))");
            }
            lines.add("0 c2s (turn 0)(turn_neck 0)(done)");
        }
        ConversionReport report = convert(write("paused.log", lines), Pairing.AUTO);
        // the server executes a body command in every step, clock running or not (its command log
        // writes them TIME,STOPPAGE): five steps, five scenes, nothing extra
        assertEquals(5, scenes.size());
        assertEquals(4, report.repeatedSenseBodies());
        assertEquals(0, report.extraActions());
        assertEquals(List.of(0, 1, 2, 0, 1), scenes.stream().map(Scene::seeAge).toList(),
                "the age counts steps since the see, not clock time");
    }

    @Test
    void anLsfAndACaptureWithSeveralCommandsPerLineConvertAlike() throws IOException {
        List<String> proxy = proxyLog(30, true);
        List<String> lsf = new ArrayList<>();
        List<String> capture = new ArrayList<>();
        for (String line : proxy.subList(1, proxy.size())) {
            String[] parts = line.split(" ", 3);
            lsf.add(parts[2]);
            capture.add("1700000000." + parts[0].replace(".", "") + " "
                    + (parts[1].equals("c2s") ? "client->server" : "server->client") + " 40001 " + parts[2]);
        }
        convert(write("p.log", proxy), Pairing.AUTO);
        List<Scene> fromProxy = new ArrayList<>(scenes);
        scenes.clear();
        convert(write("l.lsf", lsf), Pairing.AUTO);
        assertEquals(fromProxy, scenes);
        scenes.clear();
        convert(write("c.txt", capture), Pairing.AUTO);
        assertEquals(fromProxy, scenes);
        assertEquals(List.of(), warnings);
    }

    @Test
    void aMalformedCommandLosesOnlyItselfAndWhatFollowsOnItsLine() throws IOException {
        List<String> lines = new ArrayList<>(List.of("(init T (version 18))", "(init l 1 play_on)", "(ok synch_see)",
                "(sense_body 1)", "(see 1 ((b) 3 0))", "(dash 50 10)(turn_neck 5)(dash",
                "(sense_body 2)", "(turn 0)(turn_neck (x))(done)"));
        ConversionReport report = convert(write("bad.lsf", lines), Pairing.AUTO);
        assertEquals(1, report.malformed());
        assertEquals(1, report.illFormedCommands(), "(turn_neck (x)) is ill-formed, the (done) after it is read");
        assertEquals(List.of(Action.dash(50, 10), Action.turnNeck(5)), scenes.get(0).actions());
        assertEquals(List.of(Action.turn(0)), scenes.get(1).actions());
        assertEquals(6, warnings.get(0).line());
        assertTrue(warnings.get(0).problem().startsWith("column 31"), warnings.get(0).problem());
    }

    @Test
    void aCoachLogIsNamedAsSuch() throws IOException {
        Path coach = write("coach.lsf", List.of("(init HELIOS_base (version 18))", "(init l ok)",
                "(see_global 0 ((g l) -52.5 0) ((b) 0 0 0 0))", "(eye on)"));
        LogException error = assertThrows(LogException.class, () -> convert(coach, Pairing.AUTO));
        assertTrue(error.getMessage().contains("coach"), error.getMessage());
        assertTrue(error.getMessage().contains(":2"), error.getMessage());
    }
}
