package org.scenes.internal.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.World;

class SceneFileRoundTripTest {
    @TempDir
    Path dir;

    private final Grid grid = new Grid(7, -60, 60, new double[] {0.7, 3, 20});
    private final SceneFileHeader header = SceneFileHeader.of(grid,
            new SceneSource("Carleton_3.lsf.gz", SceneFixtures.OBSERVER));

    @ParameterizedTest
    @ValueSource(strings = {"scenes.json", "scenes.json.gz"})
    void everyObjectKindAndActionTypeSurvivesARoundTrip(String name) throws IOException {
        List<Scene> scenes = SceneFixtures.everyKind(grid);
        Path file = dir.resolve(name);
        SceneFileWriter.write(file, new SceneFile(header, scenes));

        SceneFile read = SceneFileReader.read(file);

        assertEquals(header, read.header());
        assertEquals(scenes, read.scenes());
        assertEquals(name.endsWith(".gz"), isGzip(file));
    }

    @Test
    void theGoalieFlagAndScenesWithoutActionSurviveAndOldFilesReadAsNotTheGoalie() throws IOException {
        SceneFileHeader goalie = SceneFileHeader.of(grid, new SceneSource("Carleton_1.lsf.gz", SceneFixtures.OBSERVER, true));
        Scene unanswered = new Scene(8, SceneFixtures.OBSERVER, List.of(), List.of());
        Path file = dir.resolve("goalie.json");
        SceneFileWriter.write(file, new SceneFile(goalie, List.of(unanswered)));
        assertTrue(Files.readString(file).contains("\"goalie\":true"));
        SceneFile read = SceneFileReader.read(file);
        assertTrue(read.header().source().goalie());
        assertEquals(List.of(unanswered), read.scenes());
        assertEquals(ActionType.NONE, read.scenes().get(0).actionType());

        Path old = dir.resolve("old.json");
        SceneFileWriter.write(old, new SceneFile(header, List.of(unanswered)));
        assertFalse(Files.readString(old).contains("goalie"), "not written when false, as before it existed");
        assertFalse(SceneFileReader.read(old).header().source().goalie());
    }

    @Test
    void seeAgeAndTheTackleFoulFlagSurviveAndOldFilesReadAsAgeZero() throws IOException {
        Scene aged = new Scene(8, SceneFixtures.OBSERVER, List.of(), List.of(Action.tackle(30, true)), null, 1);
        Scene fresh = new Scene(9, SceneFixtures.OBSERVER, List.of(), List.of(Action.tackle(-20, false)));
        Path file = dir.resolve("aged.json");
        SceneFileWriter.write(file, new SceneFile(header, List.of(aged, fresh)));
        String text = Files.readString(file);
        assertTrue(text.contains("\"seeAge\":1"), text);
        assertEquals(1, text.split("seeAge", -1).length - 1, "age 0 is not written");
        assertTrue(text.contains("\"foul\":1"), text);
        assertEquals(List.of(aged, fresh), SceneFileReader.read(file).scenes());
        assertEquals(0, SceneFileReader.read(file).scenes().get(1).seeAge());
    }

    @Test
    void theWorldBlockSurvivesARoundTripAndIsWrittenOnlyWhenAScenesHasOne() throws IOException {
        World world = new World(-12.34, 5.6, 45.5, -20, 0.12, -0.03, 7312, 0.9, 0, 3.2, -1.05, 1.5, -0.25, 2,
                List.of(new World.Player(Relation.TEAMMATE, 7, 1, 2, 0), new World.Player(Relation.UNKNOWN, 0, -3, 4.5, 0),
                        new World.Player(Relation.OPPONENT, 11, 30, -20, 12)),
                "kick_off_l", 1, 2);
        World unknown = new World(Double.NaN, Double.NaN, Double.NaN, 0, Double.NaN, Double.NaN, Double.NaN,
                Double.NaN, -1, Double.NaN, Double.NaN, Double.NaN, Double.NaN, -1, List.of(), "", 0, 0);
        Scene with = new Scene(8, SceneFixtures.OBSERVER, List.of(), List.of(Action.turn(30)), null, 1, world);
        Scene lost = new Scene(9, SceneFixtures.OBSERVER, List.of(), List.of(Action.turn(30)), null, 0, unknown);
        Scene without = new Scene(10, SceneFixtures.OBSERVER, List.of(), List.of(Action.dash(50)));
        Path file = dir.resolve("world.json");
        SceneFileWriter.write(file, new SceneFile(header, List.of(with, lost, without)));
        String text = Files.readString(file);
        assertTrue(text.startsWith("{\"format\":3"), text);
        assertEquals(2, text.split("\"world\"", -1).length - 1, text);

        SceneFile read = SceneFileReader.read(file);

        assertEquals(List.of(with, lost, without), read.scenes());
        assertEquals(3, read.header().format());
    }

    @Test
    void aFormatOneFileReadsAsScenesWithoutWorld() throws IOException {
        Path file = dir.resolve("old.json");
        Files.writeString(file, "{\"format\": 1, \"grid\": {\"columns\": 5, \"bounds\": [1, 5]}, \"scenes\": [\n"
                + "{\"cycle\": 1, \"objects\": [], \"actions\": [{\"type\": \"turn\", \"moment\": 10}]}\n]}\n");

        SceneFile read = SceneFileReader.read(file);

        assertEquals(1, read.header().format());
        assertNull(read.scenes().get(0).world());
    }

    @Test
    void formatFourIsRefusedNamingIt() throws IOException {
        Path file = dir.resolve("future.json");
        Files.writeString(file, "{\"format\":4,\"grid\":{\"columns\":5,\"bounds\":[1,5]},\"scenes\":[]}\n");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertTrue(error.getMessage().contains("scene format 4 is newer than this version of scenes reads (up to 3)"),
                error.getMessage());
    }

    @Test
    void numbersAreWrittenAsJavaWritesThemAndReadBackEqual() throws IOException {
        // tenths take a shortcut of their own: the text must be Double.toString's all the same
        // (within what a scene may hold: distances 0 to 1000 m, changes up to 10,000 either way)
        java.util.Random random = new java.util.Random(7);
        List<Double> values = new java.util.ArrayList<>(List.of(0.1, -0.1, 0.5, -0.5, 99.9, 9999.9, -9999.9,
                1234.5, 0.30000000000000004, 1e-5, 2.05, -12.34, 0.001));
        for (int i = 0; i < 2000; i++) {
            values.add(Math.rint(random.nextGaussian() * 1e4) / 10);
            values.add(random.nextGaussian() * 100);
        }
        List<SeenObject> objects = new java.util.ArrayList<>();
        for (double value : values) {
            objects.add(new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, distance(value), 1, value,
                    Double.NaN, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, grid.cell(distance(value), 1)));
        }
        List<Scene> scenes = new java.util.ArrayList<>();
        for (int from = 0; from < objects.size(); from += 200) { // a scene holds at most 256 objects
            scenes.add(new Scene(from, SceneFixtures.OBSERVER, objects.subList(from, Math.min(from + 200, objects.size())),
                    List.of(Action.turn(1))));
        }
        Path file = dir.resolve("numbers.json");
        SceneFileWriter.write(file, new SceneFile(header, scenes));
        String text = Files.readString(file);
        for (double value : values) {
            assertTrue(text.contains("[\"b\"," + written(distance(value)) + ",1," + written(value) + "]"),
                    value + " written as " + written(value));
        }
        assertEquals(scenes, SceneFileReader.read(file).scenes());
    }

    private static double distance(double value) {
        return Math.abs(value) % 1000;
    }

    private static String written(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
    }

    @Test
    void anInfiniteValueIsNeverWrittenAsAString() {
        SeenObject ball = new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, 3, 0,
                Double.POSITIVE_INFINITY, 0, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, grid.cell(3, 0));
        Scene scene = new Scene(1, SceneFixtures.OBSERVER, List.of(ball), List.of(Action.turn(1)));
        Path file = dir.resolve("infinite.json");
        IllegalArgumentException error = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> SceneFileWriter.write(file, new SceneFile(header, List.of(scene))));
        assertTrue(error.getMessage().contains("'distChange' = Infinity"), error.getMessage());
        assertTrue(Files.notExists(file), "nothing written");
    }

    @Test
    void aSceneOfMoreObjectsThanASeeCanHoldIsRefusedByTheReader() throws IOException {
        List<SeenObject> objects = new java.util.ArrayList<>();
        for (int i = 0; i < 257; i++) {
            objects.add(new SeenObject(ObjectKind.FLAG, "f c", "", 0, false, Relation.NONE, 10, 0,
                    Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, grid.cell(10, 0)));
        }
        Path file = dir.resolve("crowded.json");
        SceneFileWriter.write(file, new SceneFile(header, List.of(
                new Scene(1, SceneFixtures.OBSERVER, objects.subList(0, 256), List.of(Action.turn(1))),
                new Scene(2, SceneFixtures.OBSERVER, objects, List.of(Action.turn(1))))));
        SceneFileException error = org.junit.jupiter.api.Assertions.assertThrows(SceneFileException.class,
                () -> SceneFileReader.read(file));
        assertTrue(error.getMessage().contains("crowded.json:6") && error.getMessage().contains("at most 256 objects"),
                error.getMessage());
    }

    @Test
    void negativeZeroKeepsItsSign() throws IOException {
        SeenObject ball = new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, 3, -0.0,
                -0.0, 0.0, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, grid.cell(3, -0.0));
        Scene scene = new Scene(1, SceneFixtures.OBSERVER, List.of(ball), List.of(Action.turn(-0.0)));
        Path file = dir.resolve("zero.json");
        SceneFileWriter.write(file, new SceneFile(header, List.of(scene)));

        SeenObject read = SceneFileReader.read(file).scenes().get(0).objects().get(0);

        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(read.direction()));
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(read.distanceChange()));
        assertEquals(Double.doubleToRawLongBits(0.0), Double.doubleToRawLongBits(read.directionChange()));
        assertEquals(List.of(scene), SceneFileReader.read(file).scenes());
    }

    @Test
    void roundTripCoversEveryKindRelationAndActionType() {
        List<Scene> scenes = SceneFixtures.everyKind(grid);
        for (ObjectKind kind : ObjectKind.values()) {
            assertTrue(scenes.stream().flatMap(s -> s.objects().stream()).anyMatch(o -> o.kind() == kind), kind::toString);
        }
        for (Relation relation : Relation.values()) {
            assertTrue(scenes.stream().flatMap(s -> s.objects().stream()).anyMatch(o -> o.relation() == relation),
                    relation::toString);
        }
        for (ActionType type : ActionType.values()) {
            if (type != ActionType.NONE) {
                assertTrue(scenes.stream().flatMap(s -> s.actions().stream()).anyMatch(a -> a.type() == type),
                        type::toString);
            }
        }
    }

    @Test
    void aTruncatedFileNamesFileLineAndColumn() throws IOException {
        Path file = dir.resolve("whole.json");
        SceneFileWriter.write(file, new SceneFile(header, SceneFixtures.everyKind(grid)));
        byte[] bytes = Files.readAllBytes(file);
        Path truncated = dir.resolve("truncated.json");
        Files.write(truncated, java.util.Arrays.copyOf(bytes, bytes.length * 2 / 3));

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(truncated));

        assertTrue(error.getMessage().startsWith(truncated + ":"), error.getMessage());
        assertTrue(error.line() > 1, "line of the cut: " + error.getMessage());
        assertTrue(error.getMessage().contains("truncated"), error.getMessage());
    }

    @Test
    void aTruncatedGzipFileIsReportedNotHalfLoaded() throws IOException {
        Path file = dir.resolve("whole.json.gz");
        SceneFileWriter.write(file, new SceneFile(header, SceneFixtures.everyKind(grid)));
        byte[] bytes = Files.readAllBytes(file);
        Path truncated = dir.resolve("truncated.json.gz");
        Files.write(truncated, java.util.Arrays.copyOf(bytes, bytes.length / 2));

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(truncated));

        assertTrue(error.getMessage().contains(truncated.toString()), error.getMessage());
        assertTrue(error.getMessage().contains("truncated"), error.getMessage());
    }

    @Test
    void aFileFromAFutureFormatSaysSo() throws IOException {
        Path file = dir.resolve("future.json");
        Files.writeString(file, "{\"format\": 99, \"grid\": {\"columns\": 5, \"bounds\": [1, 5]}, \"scenes\": []}\n");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertEquals(1, error.line());
        assertTrue(error.getMessage().contains("format 99 is newer"), error.getMessage());
    }

    @Test
    void aFileWithoutFormatIsNotTakenForAScenefile() throws IOException {
        Path file = dir.resolve("other.json");
        Files.writeString(file, "{\"name\": \"something else\"}");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertTrue(error.getMessage().contains("'format' first"), error.getMessage());
    }

    @Test
    void aCellOutsideTheGridIsRejectedWithItsLine() throws IOException {
        Path file = dir.resolve("badcell.json");
        Files.writeString(file, "{\"format\": 1,\n\"grid\": {\"columns\": 5, \"rows\": 3, \"bounds\": [1, 5]},\n"
                + "\"scenes\": [\n{\"cycle\": 1, \"objects\": [{\"kind\": \"ball\", \"name\": \"b\", \"cell\": [5, 0]}],"
                + " \"actions\": []}\n]}\n");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertEquals(4, error.line());
        assertTrue(error.getMessage().contains("outside"), error.getMessage());
    }

    @Test
    void anUnknownActionParameterIsAnError() throws IOException {
        Path file = dir.resolve("badaction.json");
        Files.writeString(file, "{\"format\": 1, \"grid\": {\"columns\": 5, \"bounds\": [1, 5]}, \"scenes\": [\n"
                + "{\"cycle\": 1, \"objects\": [], \"actions\": [{\"type\": \"turn\", \"power\": 3}]}]}");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertTrue(error.getMessage().contains("has no parameter 'power'"), error.getMessage());
    }

    @Test
    void aFailedWriteLeavesThePreviousFileUntouched() throws IOException {
        Path file = dir.resolve("kept.json");
        SceneFileWriter.write(file, new SceneFile(header, SceneFixtures.everyKind(grid)));
        byte[] before = Files.readAllBytes(file);

        try (SceneFileWriter writer = SceneFileWriter.create(file, header)) {
            writer.write(SceneFixtures.everyKind(grid).get(0));
            // no commit: as if the conversion failed half-way
        }

        assertEquals(List.of(file), listDir());
        assertTrue(java.util.Arrays.equals(before, Files.readAllBytes(file)));
    }

    @Test
    void streamingReaderYieldsScenesOneByOne() throws IOException {
        Path file = dir.resolve("stream.json");
        List<Scene> scenes = SceneFixtures.everyKind(grid);
        SceneFileWriter.write(file, new SceneFile(header, scenes));

        try (SceneFileReader reader = SceneFileReader.open(file)) {
            assertEquals(grid, reader.header().grid());
            for (Scene expected : scenes) {
                assertTrue(reader.hasNext());
                assertEquals(expected, reader.next());
            }
            assertFalse(reader.hasNext());
        }
    }

    @Test
    void writtenFilesGetTheUsualPermissionsNotOwnerOnly() throws IOException {
        Path file = dir.resolve("shared.json");
        SceneFileWriter.write(file, new SceneFile(header, List.of()));
        Path plain = Files.writeString(dir.resolve("plain.txt"), "x");
        assertEquals(Files.getPosixFilePermissions(plain), Files.getPosixFilePermissions(file));
    }

    private List<Path> listDir() throws IOException {
        try (var files = Files.list(dir)) {
            return files.toList();
        }
    }

    private static boolean isGzip(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        return bytes.length > 2 && (bytes[0] & 0xff) == 0x1f && (bytes[1] & 0xff) == 0x8b;
    }
}
