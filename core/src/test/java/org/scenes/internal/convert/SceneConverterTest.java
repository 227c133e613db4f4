package org.scenes.internal.convert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.See;
import org.scenes.internal.proxylog.Direction;

class SceneConverterTest {
    @TempDir
    Path dir;

    private final List<Scene> scenes = new ArrayList<>();
    private final List<MalformedLine> warnings = new ArrayList<>();

    private Path log(String name, String... lines) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, String.join("\n", lines) + "\n");
        return file;
    }

    private ConversionReport convert(Path file) throws IOException {
        return SceneConverter.with(Grid.DEFAULT).warnings(warnings::add).build().convert(file, scenes::add);
    }

    private static final String INIT = "(init Carleton (version 9))";
    private static final String REPLY = "(init l 3 before_kick_off)";

    @Test
    void aSceneIsTheSeeWithTheActionsSentAfterIt() throws IOException {
        ConversionReport report = convert(log("a.lsf", INIT, REPLY,
                "(see 1 ((b) 10 0))", "(sense_body 1 (view_mode high normal))", "(dash 80)",
                "(see 2 ((b) 9 0))", "(turn 30)",
                "(see 3 ((b) 8 0))"));
        assertEquals(2, scenes.size());
        assertEquals(1, scenes.get(0).cycle());
        assertEquals(List.of(Action.dash(80)), scenes.get(0).actions());
        assertEquals(List.of(Action.turn(30)), scenes.get(1).actions());
        assertEquals(new Observer("Carleton", Side.LEFT, 3), scenes.get(0).observer());
        assertEquals(2, report.scenes());
        assertEquals(1, report.dropped(DropReason.NO_ACTION), "the last see had no action");
        assertEquals(0, report.dropped(DropReason.NO_SEE));
        assertEquals(3, report.sees());
        assertEquals(1, report.commands(CommandType.DASH));
        assertEquals(1L, report.actions().get(ActionType.DASH));
    }

    @Test
    void unansweredSeesAreKeptAsScenesWithoutActionWhenAsked() throws IOException {
        Path file = log("wait.lsf", INIT, REPLY,
                "(see 1 ((b) 10 0))", "(dash 80)",
                "(see 2 ((b) 9 0))", "(sense_body 2 (view_mode high normal))",
                "(see 3 ((b) 8 0))", "(turn_neck 10)",
                "(see 4 ((b) 7 0))");
        ConversionReport kept = SceneConverter.with(Grid.DEFAULT).warnings(warnings::add).keepUnanswered(true).build()
                .convert(file, scenes::add);
        assertEquals(List.of(1, 2, 3, 4), scenes.stream().map(Scene::cycle).toList());
        assertEquals(List.of(), scenes.get(1).actions(), "the teacher left see 2 unanswered");
        assertEquals(ActionType.NONE, scenes.get(3).actionType());
        assertEquals(List.of(Action.turnNeck(10)), scenes.get(2).actions());
        assertEquals(4, kept.scenes());
        assertEquals(0, kept.dropped(DropReason.NO_ACTION));
        assertEquals(2L, kept.actions().get(ActionType.NONE));

        scenes.clear();
        ConversionReport dropped = convert(file);
        assertEquals(List.of(1, 3), scenes.stream().map(Scene::cycle).toList(), "the default drops them as before");
        assertEquals(2, dropped.dropped(DropReason.NO_ACTION));
    }

    @Test
    void theGoaliesInitIsToldToTheSinkBeforeItsFirstScene() throws IOException {
        List<String> told = new ArrayList<>();
        SceneConverter.SceneSink sink = SceneConverter.SceneSink.of(scene -> told.add("scene"), () -> told.add("goalie"));
        SceneConverter.with(Grid.DEFAULT).warnings(warnings::add).build().convert(log("g.lsf", "(init Carleton (version 9) (goalie))",
                "(init l 1 before_kick_off)", "(see 1 ((b) 10 0))", "(catch 0)", "(see 2 ((b) 9 0))"), sink);
        assertEquals(List.of("goalie", "scene"), told);
        told.clear();
        SceneConverter.with(Grid.DEFAULT).warnings(warnings::add).build().convert(log("f.lsf", INIT, REPLY,
                "(see 1 ((b) 10 0))", "(dash 10)", "(see 2 ((b) 9 0))"), sink);
        assertEquals(List.of("scene"), told);
    }

    @Test
    void identicalRepeatedSeesCollapseAndCollectTheirActions() throws IOException {
        ConversionReport report = convert(log("paused.lsf", INIT, REPLY,
                "(see 0 ((b) 10 0))", "(dash 50)", "(see 0 ((b) 10 0))", "(turn_neck 20)", "(see 0 ((b) 10 0))",
                "(see 0 ((b) 10 30))", "(turn 10)"));
        assertEquals(2, scenes.size());
        assertEquals(List.of(Action.dash(50), Action.turnNeck(20)), scenes.get(0).actions());
        assertEquals(2, report.repeatedSees());
        assertEquals(0, report.droppedTotal());
        assertEquals(0, scenes.get(1).cycle(), "a different see at the same time closes the scene before it");
        assertEquals(30, scenes.get(1).objects().get(0).direction());
    }

    @Test
    void theFirstWorldChangingCommandIsPrimaryAndAtMostTwoActionsAreKept() throws IOException {
        ConversionReport report = convert(log("many.lsf", INIT, REPLY,
                "(see 5 ((b) 0.5 0))", "(turn_neck 10)", "(kick 100 20)", "(dash 40)", "(turn_neck 5)", "(say hi)"));
        assertEquals(List.of(Action.kick(100, 20), Action.turnNeck(10)), scenes.get(0).actions());
        assertEquals(ActionType.KICK, scenes.get(0).actionType());
        assertEquals(2, report.extraActions());
        assertEquals(1, report.commands(CommandType.SAY));
    }

    @Test
    void actionsBeforeTheFirstSeeAreDroppedOnce() throws IOException {
        ConversionReport report = convert(log("early.lsf", INIT, REPLY, "(move -10 0)", "(turn 20)", "(see 0 ((b) 10 0))"));
        assertEquals(0, scenes.size());
        assertEquals(1, report.dropped(DropReason.NO_SEE));
        assertEquals(1, report.dropped(DropReason.NO_ACTION));
    }

    @Test
    void illFormedCommandsAreNotActions() throws IOException {
        ConversionReport report = convert(log("bad.lsf", INIT, REPLY, "(see 0 ((b) 10 0))", "(dash)", "(see 1 ((b) 10 0))"));
        assertEquals(0, scenes.size());
        assertEquals(1, report.illFormedCommands());
        assertEquals(2, report.dropped(DropReason.NO_ACTION));
    }

    @Test
    void malformedLinesAreCountedWithFileAndLineAndStrictStops() throws IOException {
        Path file = log("broken.lsf", INIT, REPLY, "(see 0 ((b) 10 0)", "(see 1 ((b) 10 0))", "(dash 10)", "(gibberish 1)");
        ConversionReport report = convert(file);
        assertEquals(1, report.malformed());
        assertEquals(1, warnings.size());
        assertEquals(3, warnings.get(0).line());
        assertTrue(warnings.get(0).describe().startsWith(file + ":3: column"), warnings.get(0).describe());
        assertEquals(1, scenes.size());
        assertEquals(1L, report.unknown().get("gibberish"));
        LogException strict = assertThrows(LogException.class,
                () -> SceneConverter.with(Grid.DEFAULT).strict(true).build().convert(file, s -> { }));
        assertEquals(3, strict.line());
        assertTrue(strict.getMessage().startsWith(file + ":3: "), strict.getMessage());
    }

    @Test
    void relationsComeFromTheInitExchange() throws IOException {
        convert(log("rel.lsf", "(init University (version 9))", "(init r 2 before_kick_off)",
                "(see 9 ((g r) 20 0) ((g l) 80 5) ((G) 2 170) ((p \"University\" 4) 5 -40) ((p \"Carleton\") 30 40)"
                        + " ((p) 50 0) ((P) 1 180) ((f c) 10 0) ((b) 0.8 -44))",
                "(dash 10)"));
        List<Relation> relations = scenes.get(0).objects().stream().map(SeenObject::relation).toList();
        assertEquals(List.of(Relation.OWN, Relation.OPPONENT, Relation.UNKNOWN, Relation.TEAMMATE, Relation.OPPONENT,
                Relation.UNKNOWN, Relation.UNKNOWN, Relation.NONE, Relation.NONE), relations);
        List<Cell> cells = scenes.get(0).objects().stream().map(SeenObject::cell).toList();
        assertEquals(new Cell(2, 2), cells.get(0));
        assertEquals(new Cell(0, 1), cells.get(3), "5 m at -40 degrees: leftmost column, middle row");
        assertEquals(new Cell(0, 0), cells.get(8), "0.8 m at -44 degrees: kickable row");
        assertEquals(20, scenes.get(0).objects().get(0).distance(), "continuous values are kept");
    }

    @Test
    void seenObjectsIsTheSameStepTheConverterUses() {
        See see = (See) new MessageParser().parse("(see 3 ((g l) 20 -10) ((p \"A\" 1) 2 3 0 0 10 20))");
        List<SeenObject> objects = SceneConverter.seenObjects(see, new Observer("A", Side.LEFT, 5), Grid.of(3, 10));
        assertEquals(Relation.OWN, objects.get(0).relation());
        assertEquals(new Cell(1, 1), objects.get(0).cell());
        assertEquals(Relation.TEAMMATE, objects.get(1).relation());
        assertEquals(10, objects.get(1).bodyFacing());
        assertEquals(new Cell(1, 0), objects.get(1).cell());
    }

    @Test
    void goalsAreUnknownWhenTheSideWasNeverLearned() throws IOException {
        convert(log("noinit.lsf", "(see 1 ((g r) 20 0) ((p \"X\" 1) 5 0))", "(dash 10)"));
        assertEquals(Relation.UNKNOWN, scenes.get(0).objects().get(0).relation());
        assertEquals(Relation.UNKNOWN, scenes.get(0).objects().get(1).relation());
        assertEquals(Observer.UNKNOWN, scenes.get(0).observer());
    }

    @Test
    void anLsfLogDoesNotSayWhichWayAMessageWent() throws IOException {
        try (LogReader reader = LogReader.open(log("plain.lsf", INIT, REPLY))) {
            assertTrue(reader.next());
            assertNull(reader.direction());
        }
    }

    @Test
    void theProxyFormatIsDetectedAndUnescaped() throws IOException {
        Path file = log("game.log", "#scenes-proxy-log 1", "# team Carleton unum 3 side l",
                "0.000100 c2s (init Carleton (version 9))\\0\\0", "0.010000 s2c (init l 3 before_kick_off)",
                "0.100000 s2c (see 0 ((b) 10 0))", "0.110000 c2s (say \"a\\\\b\\x41\")", "0.120000 c2s (dash 50)",
                "0.130000 s2c", "0.200000 s2c (see 1 ((b) 9 0))");
        try (LogReader reader = LogReader.open(file)) {
            assertEquals(LogFormat.NATIVE, reader.format());
            assertTrue(reader.next());
            assertEquals("(init Carleton (version 9))", reader.text());
            assertEquals(Direction.CLIENT_TO_SERVER, reader.direction());
            assertEquals(0.0001, reader.time(), 1e-9);
            assertEquals(3, reader.line());
            reader.next();
            assertEquals(Direction.SERVER_TO_CLIENT, reader.direction());
            reader.next();
            reader.next();
            assertEquals("(say \"a\\bA\")", reader.text());
        }
        ConversionReport report = convert(file);
        assertEquals(1, scenes.size());
        assertEquals(new Observer("Carleton", Side.LEFT, 3), scenes.get(0).observer());
        assertEquals(0, report.malformed());
    }

    @Test
    void theCaptureFormatIsDetectedAndGzipIsRead() throws IOException {
        Path file = dir.resolve("capture.log.gz");
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(file))) {
            out.write(String.join("\n",
                    "1795423810.377263 client->server 50919 (init KrisA (version 9))",
                    "1795423810.383147 server->client 50919 (init l 1 before_kick_off)",
                    "1795423810.504982 server->client 50919 (see 0 ((b) 5 0))",
                    "1795423810.594238 client->server 50919 (turn 40.0)",
                    "1795423810.6 sideways 50919 (turn 40.0)",
                    "1795423810.7 server->client 50920 (see 1 ((b) 5 0))").getBytes(StandardCharsets.UTF_8));
        }
        try (LogReader reader = LogReader.open(file)) {
            assertEquals(LogFormat.CAPTURE, reader.format());
        }
        ConversionReport report = convert(file);
        assertEquals(1, scenes.size());
        assertEquals(List.of(Action.turn(40)), scenes.get(0).actions());
        assertEquals(2, report.malformed(), "the line with a bad direction and the other client's line");
        assertEquals(5, warnings.get(0).line());
        assertTrue(warnings.get(1).problem().contains("a second client (port 50920, first was 50919)"),
                warnings.get(1).problem());
    }

    @Test
    void emptyLogsConvertToNothing() throws IOException {
        ConversionReport empty = convert(log("empty.lsf"));
        assertEquals(0, empty.scenes());
        assertEquals(0, empty.malformed());
        ConversionReport blank = convert(log("blank.log", "#scenes-proxy-log 1", "", "# client 127.0.0.1:40001"));
        assertEquals(0, blank.messages());
        assertEquals(0, blank.malformed());
    }

    @Test
    void aBrokenProxyFrameIsAMalformedLine() throws IOException {
        ConversionReport report = convert(log("frames.log", "#scenes-proxy-log 1", "0.1 s2c (see 0 ((b) 1 0))",
                "0.2 up (dash 10)", "x.y c2s (dash 10)", "0.3 c2s (turn 10)"));
        assertEquals(2, report.malformed());
        assertEquals("direction must be c2s or s2c", warnings.get(0).problem());
        assertEquals(4, warnings.get(1).line());
        assertEquals(List.of(Action.turn(10)), scenes.get(0).actions());
    }

    @Test
    void aBadEscapeInAProxyLogIsAMalformedLine() throws IOException {
        ConversionReport report = convert(log("escapes.log", "#scenes-proxy-log 1", "0.1 s2c (see 0 ((b) 1 0))",
                "0.2 c2s (say \\q)", "0.3 c2s (say \\x4)", "0.4 c2s (turn 10)"));
        assertEquals(2, report.malformed());
        assertTrue(warnings.get(0).problem().contains("unknown escape \\q"), warnings.get(0).problem());
        assertTrue(warnings.get(1).problem().contains("two hex digits"), warnings.get(1).problem());
        assertEquals(List.of(Action.turn(10)), scenes.get(0).actions());
    }

    @Test
    void anUnknownFormatIsRejectedWithTheFileName() throws IOException {
        Path file = log("notes.txt", "hello there");
        LogException error = assertThrows(LogException.class, () -> LogReader.open(file));
        assertTrue(error.getMessage().startsWith(file + ":1: not a player log"), error.getMessage());
    }

    @Test
    void longLinesAndCrLfAreRead() throws IOException {
        // a line of about 45 KB: 250 objects (a see holds at most 256) with long-written numbers
        StringBuilder see = new StringBuilder("(see 4");
        for (int i = 0; i < 250; i++) {
            see.append(" ((f c) 10.").append("0".repeat(170)).append(' ').append(i % 90).append(')');
        }
        see.append(')');
        assertTrue(see.length() > 45_000);
        Path file = dir.resolve("long.lsf");
        Files.writeString(file, INIT + "\r\n" + see + "\r\n(dash 1)\r\n");
        convert(file);
        assertEquals(250, scenes.get(0).objects().size());
        assertEquals(10, scenes.get(0).objects().get(0).distance(), 0);
    }
}
