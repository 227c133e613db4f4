package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.DropReason;
import org.scenes.internal.convert.LogReader;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.Unknown;
import org.scenes.simulator.SyntheticScenes;

/**
 * What the tests on the shared real recordings check that does not depend on real data, checked
 * on data the project makes itself (a seeded simulated game, {@link SimulatedGame}, and
 * {@link SyntheticScenes}), so a clone without the recordings still covers it: the converter's
 * accounting (core's SharedLogsTest), typed messages without leftovers (RealServerTrafficTest),
 * the compact knowledge base (KnowledgeBaseTest) and the packed scans of the object-set metrics
 * and of ball-goal against exhaustive ones (PackedScanTest, PackedBallGoalTest).
 */
class SimulatedDataTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();
    private static final String[] TEAMS = {"Carleton", "University"};
    private static final int PLAYERS = 5;

    private static List<Scene> stored;
    private static List<Scene> queries;

    @BeforeAll
    static void synthetic() {
        stored = new ArrayList<>();
        SyntheticScenes.generate(3, 1500, Grid.DEFAULT, stored::add);
        List<Scene> more = new ArrayList<>();
        SyntheticScenes.generate(4, 25, Grid.DEFAULT, more::add);
        queries = more;
    }

    private static ConversionReport convert(Path log, List<Scene> scenes) throws IOException {
        return SceneConverter.with(Grid.DEFAULT).strict(true).build().convert(log, scenes == null ? s -> { } : scenes::add);
    }

    @Test
    void everySeeAndEveryActionOfASimulatedLogIsAccountedFor() throws IOException {
        for (String team : TEAMS) {
            for (int unum = 1; unum <= PLAYERS; unum++) {
                Path log = SimulatedGame.log(team, unum);
                ConversionReport report = convert(log, null);
                long dash = report.commands(CommandType.DASH);
                long turn = report.commands(CommandType.TURN);
                long kick = report.commands(CommandType.KICK);
                assertEquals(0, report.malformed(), log.toString());
                assertEquals(Map.of(), report.unknown(), log.toString());
                assertTrue(report.scenes() > SimulatedGame.CYCLES / 3, log + ": scenes " + report.scenes());
                assertEquals(1, report.dropped(DropReason.NO_SEE), log + ": the initial move before the first see");
                // every see is a scene, a no-action drop or a collapsed repeat
                assertEquals(report.sees(), report.scenes() + report.dropped(DropReason.NO_ACTION) + report.repeatedSees(),
                        log.toString());
                // every action sent after a see is either a scene's action or an extra one; so are the
                // kick-off moves sent again after goals and half time (all moves but the first)
                long movesAgain = report.commands(CommandType.MOVE) - 1;
                assertEquals(dash + turn + kick + movesAgain, report.scenes() + report.extraActions(), log.toString());
            }
        }
    }

    @Test
    void observersAndRelationsComeFromTheLogs() throws IOException {
        List<Scene> scenes = new ArrayList<>();
        convert(SimulatedGame.log("University", 2), scenes);
        Scene any = scenes.get(scenes.size() / 2);
        assertEquals("University", any.observer().team());
        assertEquals('r', any.observer().side().letter());
        assertEquals(2, any.observer().uniformNumber());
        assertTrue(scenes.stream().flatMap(s -> s.objects().stream()).anyMatch(o -> o.relation() == Relation.TEAMMATE));
        assertEquals(0, scenes.stream().flatMap(s -> s.objects().stream())
                .filter(o -> o.relation() == Relation.TEAMMATE).filter(o -> !o.team().equals("University")).count());
        assertEquals(0, scenes.stream().flatMap(s -> s.objects().stream())
                .filter(o -> o.relation() == Relation.OWN).filter(o -> !o.name().equals("g r")).count());
    }

    @Test
    void everySimulatedMessageIsTypedWithoutLeftovers() throws IOException {
        MessageParser parser = new MessageParser();
        int messages = 0;
        try (LogReader reader = LogReader.open(SimulatedGame.log("Carleton", 3))) {
            while (reader.next()) {
                assertEquals(null, reader.problem(), reader.text());
                Message message = parser.parse(reader.buffer(), reader.offset(), reader.length());
                assertTrue(!(message instanceof Unknown), reader.text());
                assertEquals(List.of(), message.leftovers(), reader.text());
                messages++;
            }
        }
        // a sense_body every cycle and a see on two cycles of three, at least
        assertTrue(messages > SimulatedGame.CYCLES * 5 / 3, "messages " + messages);
    }

    @Test
    void everySimulatedSceneComesBackEqualFromTheKnowledgeBase() throws IOException {
        long objects = 0;
        long storedBytes = 0;
        for (String team : TEAMS) {
            for (int unum = 1; unum <= 2; unum++) {
                List<Scene> original = new ArrayList<>();
                SceneConverter.with(Grid.DEFAULT).build().convert(SimulatedGame.log(team, unum), original::add);
                KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, original);
                assertEquals(original, knowledge.scenes(), team + " " + unum);
                objects += original.stream().mapToInt(s -> s.objects().size()).sum();
                storedBytes += knowledge.storedBytes();
            }
        }
        double bytesPerObject = (double) storedBytes / objects;
        // 8 doubles alone take 64 bytes per object as records; the store must stay an order below
        assertTrue(bytesPerObject < 9, "bytes per object " + bytesPerObject);
    }

    @Test
    void objectSetMetricsFindTheNeighboursOfAnExhaustiveScan() {
        assertSameNeighbours("continuous", Map.of());
        assertSameNeighbours("continuous", Map.of("space", "polar", "row-weight", "2", "log-distance", "true"));
        assertSameNeighbours("continuous", Map.of("matching", "optimal"));
        assertSameNeighbours("cell", Map.of());
        assertSameNeighbours("projection", Map.of());
    }

    @Test
    void ballGoalIndexAndScanFindTheNeighboursOfAnExhaustiveScan() {
        assertSameNeighbours("ball-goal", Map.of());
        assertSameNeighbours("ball-goal", Map.of("index", "false"));
        assertSameNeighbours("ball-goal", Map.of("missing", "3", "angle-weight", "2"));
    }

    /** The recognizer at k = 1, 5, 15 against every distance sorted: same indices, same distances bit for bit. */
    private static void assertSameNeighbours(String metricName, Map<String, String> options) {
        PluginConfig config = PluginConfig.DEFAULT.withOptions(options);
        SceneMetric metric = REGISTRY.metric(metricName, config);
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, stored);
        int[] ks = {1, 5, 15};
        List<Recognizer> recognizers = new ArrayList<>();
        for (int k : ks) {
            recognizers.add(new Recognizer(knowledge, () -> REGISTRY.metric(metricName, config), k));
        }
        for (int q = 0; q < queries.size(); q++) {
            List<Neighbour> all = new ArrayList<>();
            for (int i = 0; i < stored.size(); i++) {
                all.add(new Neighbour(stored.get(i), i, metric.distance(queries.get(q), stored.get(i))));
            }
            all.sort(Comparator.comparingDouble(Neighbour::distance).thenComparingInt(Neighbour::index));
            for (int r = 0; r < ks.length; r++) {
                List<Neighbour> actual = recognizers.get(r).nearest(queries.get(q));
                assertEquals(ks[r], actual.size());
                for (int i = 0; i < ks[r]; i++) {
                    String what = metricName + " " + options + ", k=" + ks[r] + ", query " + q + ", neighbour " + i;
                    assertEquals(all.get(i).index(), actual.get(i).index(), what);
                    assertEquals(Double.doubleToLongBits(all.get(i).distance()), Double.doubleToLongBits(actual.get(i).distance()), what);
                }
            }
        }
    }
}
