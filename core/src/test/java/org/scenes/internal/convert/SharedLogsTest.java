package org.scenes.internal.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.scenes.api.Grid;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.internal.protocol.CommandType;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/**
 * Converts the recorded games of the shared data set and pins counts that were derived
 * independently with the shell, not with this code:
 *
 * <pre>
 * zgrep -c '^(see ' LOG                                               # see messages
 * zcat LOG | grep -o '^(\(dash\|turn\|kick\|move\) ' | sort | uniq -c  # commands by type
 * zcat LOG | awk '/^\(see /{ if ($0==last) {rep++; next} if (p) { if (a) sc++; else na++ } p=1; a=0; last=$0; next }
 *   /^\((dash|turn|kick|move|turn_neck|catch|tackle) /{ if (p) a=1; else ns=1 }
 *   END { if (p) { if (a) sc++; else na++ } print sc, na, rep, ns }'   # scenes, no-action, repeats, no-see
 * </pre>
 *
 * (for the capture, {@code cut -d' ' -f4-} first strips time, direction and port). Differences
 * between raw counts and scenes are explained per case: every log starts with one {@code move}
 * sent before the first {@code see} (one NO_SEE drop), and a scene keeps one world-changing
 * action, so in the state-based games (up to ~70 {@code turn}s per {@code see}) almost all
 * turns are extra actions rather than scenes. University_3 of game 2 stood still most of the game
 * (260 dashes, 48 turns), hence 2234 sees without action. The same accounting on simulated games:
 * {@code SimulatedDataTest} in the tests module.
 */
@RequiresSharedData
class SharedLogsTest {
    private static final Path DATA = SharedData.data();

    private static ConversionReport convert(Path log, List<Scene> scenes) throws IOException {
        return SceneConverter.with(Grid.DEFAULT).strict(true).build().convert(log, scenes == null ? s -> { } : scenes::add);
    }

    @Test
    void all27KrisletLogsConvertWithoutMalformedLines() throws IOException {
        List<Path> logs;
        try (Stream<Path> files = Files.walk(DATA.resolve("krislet"))) {
            logs = files.filter(p -> p.toString().endsWith(".lsf.gz")).sorted().toList();
        }
        assertEquals(27, logs.size());
        ConversionReport total = new ConversionReport();
        for (Path log : logs) {
            total.add(convert(log, null)); // strict: the first malformed line would throw
        }
        assertEquals(0, total.malformed());
        assertEquals(Map.of(), total.unknown());
        // zcat krislet/*/*.lsf.gz | grep -c '^(see '
        assertEquals(75680, total.sees());
        // zcat krislet/*/*.lsf.gz | grep -c '^(dash '
        assertEquals(40702, total.commands(CommandType.DASH));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
        // log, sees, dash, turn, kick, move, scenes, no action, repeated sees, extra actions
        "krislet/classic-game1/Carleton_1.lsf.gz,      3531, 2041,    626, 10, 1, 2592,  859,  80,     85",
        "krislet/classic-game2/University_3.lsf.gz,    2614,  260,     48,  0, 1,  281, 2234,  99,     27",
        "krislet/statebased-game3/University_5.lsf.gz, 2064, 1173, 150020,  5, 1, 1592,  468,   4, 149606",
        "rcssserver19/krislet-3v3-player1.log.gz,       473,  240,    109,  4, 1,  349,  117,   7,      4",
    })
    void pinnedCounts(String log, long sees, long dash, long turn, long kick, long move, long scenes,
                      long noAction, long repeats, long extra) throws IOException {
        ConversionReport report = convert(DATA.resolve(log), null);
        assertEquals(sees, report.sees());
        assertEquals(dash, report.commands(CommandType.DASH));
        assertEquals(turn, report.commands(CommandType.TURN));
        assertEquals(kick, report.commands(CommandType.KICK));
        assertEquals(move, report.commands(CommandType.MOVE));
        assertEquals(scenes, report.scenes());
        assertEquals(noAction, report.dropped(DropReason.NO_ACTION));
        assertEquals(1, report.dropped(DropReason.NO_SEE), "the initial move before the first see");
        assertEquals(repeats, report.repeatedSees());
        // every see is a scene, a no-action drop or a collapsed repeat
        assertEquals(sees, scenes + noAction + repeats);
        // every action sent after a see is either a scene's action or an extra one
        assertEquals(dash + turn + kick, scenes + extra);
        assertEquals(0, report.malformed());
    }

    @Test
    void observersAndRelationsComeFromTheLogs() throws IOException {
        List<Scene> scenes = new java.util.ArrayList<>();
        convert(DATA.resolve("krislet/classic-game1/University_2.lsf.gz"), scenes);
        Scene any = scenes.get(scenes.size() / 2);
        assertEquals("University", any.observer().team());
        assertEquals('r', any.observer().side().letter());
        assertEquals(2, any.observer().uniformNumber());
        long teammates = scenes.stream().flatMap(s -> s.objects().stream())
                .filter(o -> o.relation() == Relation.TEAMMATE).filter(o -> !o.team().equals("University")).count();
        assertEquals(0, teammates);
        long ownGoals = scenes.stream().flatMap(s -> s.objects().stream())
                .filter(o -> o.relation() == Relation.OWN).filter(o -> !o.name().equals("g r")).count();
        assertEquals(0, ownGoals);
    }
}
