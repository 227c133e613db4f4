package org.scenes.internal.match;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/** The compact store gives back every scene exactly, in far less memory than scene objects. */
class KnowledgeBaseTest {
    private static final Path KRISLET = SharedData.resolve("krislet");

    /** Simulated scenes: {@code SimulatedDataTest} in the tests module. */
    @Test
    @RequiresSharedData
    void everyRealKrisletSceneComesBackEqual() throws IOException {
        List<Path> logs;
        try (Stream<Path> files = Files.walk(KRISLET)) {
            logs = files.filter(p -> p.toString().endsWith(".lsf.gz")).sorted().toList();
        }
        long objects = 0;
        long stored = 0;
        int scenes = 0;
        for (Path log : logs) {
            List<Scene> original = new ArrayList<>();
            SceneConverter.with(Grid.DEFAULT).build().convert(log, original::add);
            KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, original);
            assertEquals(original, knowledge.scenes(), log.toString());
            scenes += original.size();
            objects += original.stream().mapToInt(s -> s.objects().size()).sum();
            stored += knowledge.storedBytes();
        }
        double bytesPerObject = (double) stored / objects;
        System.out.printf("%d scenes, %.1f objects per scene, %.1f bytes per object stored%n",
                scenes, (double) objects / scenes, bytesPerObject);
        // 8 doubles alone take 64 bytes per object as records; the store must stay an order below
        assertTrue(bytesPerObject < 9, "bytes per object " + bytesPerObject);
    }

    @Test
    void worldModelsComeBackEqualWithTheirScenesAndMemory() {
        Observer observer = new Observer("Us", Side.RIGHT, 4);
        World world = new World(-12.34, 5.6, 45.5, -20, 0.12, -0.03, 7312, 0.9, 0, 3.2, -1.05, 1.5, -0.25, 2,
                List.of(new World.Player(Relation.TEAMMATE, 7, 1, 2, 0), new World.Player(Relation.UNKNOWN, 0, -3, 4.5, 0)),
                "kick_off_l", 1, 2);
        World unknown = new World(Double.NaN, Double.NaN, Double.NaN, 0, Double.NaN, Double.NaN, Double.NaN,
                Double.NaN, -1, Double.NaN, Double.NaN, Double.NaN, Double.NaN, -1, List.of(), "", 0, 0);
        Scene first = new Scene(1, observer, List.of(), List.of(Action.turn(10)), null, 0, unknown);
        Scene second = new Scene(2, observer, List.of(), List.of(Action.dash(80)), first, 1, world);
        Scene without = new Scene(3, observer, List.of(), List.of(Action.kick(50, 10)));
        List<Scene> original = List.of(first, second, without);

        assertEquals(original, KnowledgeBase.of(Grid.DEFAULT, original).scenes());
    }

    @Test
    void unusualValuesAreKeptToTheBit() {
        Grid grid = Grid.DEFAULT;
        double[] values = {-0.0, 0.1 + 0.2, Math.PI, 1e300, -1e-300, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.longBitsToDouble(0x7ff8000000000123L), 12.34, -45, 1e15, 123456789.5};
        List<SeenObject> objects = new ArrayList<>();
        for (double value : values) {
            objects.add(new SeenObject(ObjectKind.PLAYER, "p", "Team with spaces", 11, true, Relation.OPPONENT,
                    value, -value, value, value, value, value, value, 't', new Cell(7, 9)));
        }
        objects.add(SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, Double.NaN, Double.NaN, grid));
        objects.add(new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, 3, 7,
                -0.02, 0.1, Double.NaN, Double.NaN, Double.NaN, 'k', grid.cell(3, 7)));
        // a remembered object keeps its confidence
        objects.add(objects.get(objects.size() - 1).remembered(4, 60, 0.7 / 3, grid));
        Scene earlier = new Scene(-5, Observer.UNKNOWN, objects.subList(0, 2), List.of(Action.turn(-0.0)));
        Scene scene = new Scene(Integer.MAX_VALUE, new Observer("Carleton", Side.RIGHT, 9), objects,
                List.of(Action.kick(100, Double.longBitsToDouble(0x7ff8000000000001L)),
                        new Action(ActionType.TURN_NECK, 1e-9, Double.NaN)), earlier);
        Scene back = KnowledgeBase.of(grid, List.of(scene, earlier)).scene(0);
        assertEquals(scene, back);
        assertEquals(earlier, back.previous());
        for (int i = 0; i < values.length; i++) {
            SeenObject object = back.objects().get(i);
            assertEquals(Double.doubleToRawLongBits(values[i]), Double.doubleToRawLongBits(object.distance()));
            assertEquals(Double.doubleToRawLongBits(-values[i]), Double.doubleToRawLongBits(object.direction()));
            assertEquals(new Cell(7, 9), object.cell());
        }
        assertEquals(0x7ff8000000000001L, Double.doubleToRawLongBits(back.primaryAction().second()));
        SeenObject remembered = back.objects().get(back.objects().size() - 1);
        assertTrue(remembered.remembered());
        assertEquals(0.7 / 3, remembered.confidence());
        assertFalse(back.objects().get(0).remembered());
    }

    @Test
    void loadStreamsFilesAndRefusesMixedGrids(@TempDir Path dir) throws IOException {
        List<Scene> first = TestScenes.random(1, 300);
        List<Scene> second = TestScenes.random(2, 200);
        Path a = write(dir.resolve("a.json.gz"), Grid.DEFAULT, first);
        Path b = write(dir.resolve("b.json"), Grid.DEFAULT, second);
        KnowledgeBase knowledge = KnowledgeBase.load(List.of(a, b), List::of);
        List<Scene> all = new ArrayList<>(SceneFileReader.read(a).scenes());
        all.addAll(SceneFileReader.read(b).scenes());
        assertEquals(500, all.size());
        assertEquals(all, knowledge.scenes());

        Grid other = Grid.of(3, 2);
        Path c = write(dir.resolve("c.json"), other, second.stream().map(s -> s.regrid(other)).toList());
        Grid.MismatchException mixed = assertThrows(Grid.MismatchException.class,
                () -> KnowledgeBase.load(List.of(a, c), List::of));
        assertTrue(mixed.getMessage().startsWith(c.toString()), mixed.getMessage());
    }

    @Test
    void aBuiltKnowledgeBaseTakesNoMoreScenes() {
        KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT).add(TestScenes.random(3, 1).get(0));
        assertEquals(1, builder.build().size());
        assertThrows(IllegalStateException.class, () -> builder.add(TestScenes.random(4, 1).get(0)));
    }

    private static Path write(Path path, Grid grid, List<Scene> scenes) throws IOException {
        SceneFileWriter.write(path, new SceneFile(SceneFileHeader.of(grid, new SceneSource("test", Observer.UNKNOWN)), scenes));
        return path;
    }
}
