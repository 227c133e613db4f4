package org.scenes.internal.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.World;

/** Format 3 writes objects and world players as arrays; formats 1 and 2 still read as before. */
class CompactSceneFormatTest {
    @TempDir
    Path dir;

    private final Grid grid = Grid.DEFAULT;
    private final SceneFileHeader header = SceneFileHeader.of(grid, new SceneSource("Carleton_3.lsf", SceneFixtures.OBSERVER));

    /** A format-2 file as the previous writer wrote it: named fields, kinds, cells, players as objects. */
    private static final String FORMAT_TWO = """
            {"format":2
            ,"grid":{"columns":5,"rows":3,"minAngle":-45.0,"maxAngle":45.0,"bounds":[1.0,5.0]}
            ,"source":{"log":"Carleton_3.lsf","team":"Carleton","side":"l","unum":3}
            ,"scenes":[
            {"cycle":57,"objects":[{"kind":"ball","name":"b","dist":2.7,"dir":-5,"distChange":-0.1,"dirChange":3.2,"cell":[2,1]},\
            {"kind":"goal","name":"g r","relation":"opponent","dist":44.7,"dir":12,"cell":[3,2]},\
            {"kind":"flag","name":"f r t","dir":-31,"cell":[0,2]},\
            {"kind":"player","name":"p","team":"Carleton","unum":7,"goalie":true,"relation":"teammate","dist":10.5,\
            "dir":-20,"distChange":0.2,"dirChange":-1,"bodyFacing":45,"headFacing":30,"pointDir":12,"mark":"t","cell":[1,2]}],\
            "actions":[{"type":"dash","power":100,"primary":true}],\
            "world":{"x":-9.45,"y":-0.78,"body":4,"neck":0,"vx":-0.03,"vy":0,"stamina":7175,"effort":1,"age":0,\
            "ball":{"x":-0.47,"y":-0.16,"vx":-0.03,"vy":0,"age":0},\
            "players":[{"relation":"opponent","unum":2,"x":8.53,"y":-3.63,"age":0},{"relation":"unknown","x":-9.48,"y":-0.18,"age":4}],\
            "playMode":"kick_off_r","score":[0,0]}}
            ]}
            """;

    @Test
    void aFormatTwoFileReadsAsTheScenesItsFormatThreeRewriteHolds() throws IOException {
        Path old = dir.resolve("old.json");
        Files.writeString(old, FORMAT_TWO);
        SceneFile read = SceneFileReader.read(old);
        assertEquals(2, read.header().format());

        Path rewritten = dir.resolve("new.json");
        SceneFileWriter.write(rewritten, new SceneFile(SceneFileHeader.of(read.header().grid(), read.header().source()),
                read.scenes()));
        SceneFile again = SceneFileReader.read(rewritten);

        assertEquals(3, again.header().format());
        assertEquals(read.scenes(), again.scenes());
        String text = Files.readString(rewritten);
        // the relations follow from the observer (team Carleton, left side): not written
        assertTrue(text.contains("\"objects\":[[\"b\",2.7,-5,-0.1,3.2],[\"g r\",44.7,12],[\"f r t\",null,-31],"
                + "[\"p\",10.5,-20,0.2,-1,45,30,12,{\"team\":\"Carleton\",\"unum\":7,\"goalie\":true,\"mark\":\"t\"}]]"),
                text);
        assertTrue(text.contains("\"players\":[[\"opponent\",2,8.53,-3.63,0],[\"unknown\",null,-9.48,-0.18,4]]"), text);
        assertTrue(text.length() < FORMAT_TWO.length() * 3 / 4, text.length() + " of " + FORMAT_TWO.length());
    }

    @Test
    void aSceneOfFlagsTakesUnderAThirdOfItsFormatTwoSize() throws IOException {
        // most of a see is flags: what the compact form saves is most of the file
        String[] flags = {"f c", "f c t", "f c b", "f l t", "f l b", "f p r b", "f p r c", "f p r t", "f t 0", "f b 0"};
        List<SeenObject> objects = new java.util.ArrayList<>();
        StringBuilder longForm = new StringBuilder("{\"format\":2,\"grid\":{\"columns\":5,\"bounds\":[1,5]},\"scenes\":[{\"cycle\":1,"
                + "\"objects\":[");
        for (int i = 0; i < flags.length; i++) {
            double distance = 20.1 + 7 * i;
            int direction = -40 + 9 * i;
            SeenObject flag = SeenObject.simple(ObjectKind.FLAG, flags[i], Relation.NONE, distance, direction, grid);
            objects.add(flag);
            longForm.append(i == 0 ? "" : ",").append("{\"kind\":\"flag\",\"name\":\"").append(flags[i]).append("\",\"dist\":")
                    .append(distance).append(",\"dir\":").append(direction).append(",\"cell\":[").append(flag.cell().column())
                    .append(',').append(flag.cell().row()).append("]}");
        }
        longForm.append("],\"actions\":[{\"type\":\"turn\",\"moment\":30,\"primary\":true}]}]}");
        Path old = dir.resolve("old.json");
        Files.writeString(old, longForm);
        Path compact = dir.resolve("new.json");
        Scene scene = new Scene(1, SceneFixtures.OBSERVER, objects, List.of(Action.turn(30)));
        SceneFileWriter.write(compact, new SceneFile(SceneFileHeader.of(grid, new SceneSource("", SceneFixtures.OBSERVER)),
                List.of(scene)));

        assertEquals(SceneFileReader.read(old).scenes().get(0).objects(), SceneFileReader.read(compact).scenes().get(0).objects());
        String objectsText = Files.readString(compact).replaceAll("(?s).*\"objects\":(\\[.*\\]),\"actions\".*", "$1");
        String oldObjectsText = longForm.toString().replaceAll("(?s).*\"objects\":(\\[.*\\]),\"actions\".*", "$1");
        assertTrue(objectsText.length() * 3 < oldObjectsText.length(), objectsText + " against " + oldObjectsText);
    }

    @Test
    void aRelationTheObserverDoesNotImplyIsWrittenAndReadBack() throws IOException {
        // made by hand or by another tool: the right side's own goal is "g r", not "g l"
        SeenObject goal = SeenObject.simple(ObjectKind.GOAL, "g l", Relation.OWN, 20, 1, grid);
        SeenObject stranger = new SeenObject(ObjectKind.PLAYER, "p", "Carleton", 4, false, Relation.OPPONENT, 12, 3,
                Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, grid.cell(12, 3));
        Scene scene = new Scene(4, new org.scenes.api.Observer("University", org.scenes.api.Side.RIGHT, 1),
                List.of(goal, stranger), List.of(Action.turn(10)));
        Path file = dir.resolve("relations.json");
        SceneFileWriter.write(file, new SceneFile(header, List.of(scene)));

        String text = Files.readString(file);
        assertTrue(text.contains("[\"g l\",20,1,{\"relation\":\"own\"}]"), text);
        assertTrue(text.contains("{\"team\":\"Carleton\",\"unum\":4}"), "Carleton is not University's team: " + text);
        assertEquals(List.of(scene), SceneFileReader.read(file).scenes());
    }

    @Test
    void anObserverAfterTheObjectsItWouldRelateToIsRefused() throws IOException {
        Path file = dir.resolve("late.json");
        Files.writeString(file, "{\"format\":3,\"grid\":{\"columns\":5,\"bounds\":[1,5]},\"scenes\":[\n"
                + "{\"cycle\":1,\"objects\":[[\"g l\",3,0]],\"observer\":{\"team\":\"A\",\"side\":\"r\"},\"actions\":[]}\n]}\n");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertTrue(error.getMessage().startsWith(file + ":2:"), error.getMessage());
        assertTrue(error.getMessage().contains("'observer' must come before 'objects'"), error.getMessage());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "[\"x c\",1,2]|an object's name starts with b, g, f, l or p",
        "[\"b\",1,2,3,4,5,6,7,8]|at most 7 numbers after its name",
        "[\"b\",{\"relation\":\"own\"},1]|the end of the object array after its identity",
        "[\"b\",-1,0]|'dist' must be a finite number from 0 to 1000, not -1.0",
        "[\"b\",1,0,null,null,200]|'bodyFacing' must be a finite number from -180 to 180",
        "[\"b\",\"1\",0]|expected a number but found a string",
        "[\"p\",1,0,{\"mark\":\"x\"}]|mark must be \"t\" or \"k\"",
        "{\"kind\":\"ball\",\"name\":\"b\",\"cell\":[2,0]}|expected an object array [name, dist, dir, ...] but found an object",
    })
    void aBrokenObjectArrayIsRefusedNamingFileAndLine(String object, String message) throws IOException {
        Path file = dir.resolve("broken.json");
        Files.writeString(file, "{\"format\":3,\"grid\":{\"columns\":5,\"bounds\":[1,5]},\"scenes\":[\n"
                + "{\"cycle\":1,\"objects\":[[\"f c\",3,0]],\"actions\":[]},\n"
                + "{\"cycle\":2,\"objects\":[" + object + "],\"actions\":[]}\n]}\n");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertTrue(error.getMessage().startsWith(file + ":3:"), error.getMessage());
        assertTrue(error.getMessage().contains(message), error.getMessage());
    }

    @Test
    void aBrokenWorldPlayerIsRefusedNamingItsShape() throws IOException {
        Path file = dir.resolve("broken.json");
        Files.writeString(file, "{\"format\":3,\"grid\":{\"columns\":5,\"bounds\":[1,5]},\"scenes\":[\n"
                + "{\"cycle\":1,\"objects\":[],\"actions\":[],\"world\":{\"players\":[[\"opponent\",2,8.5,-3.6]],\"score\":[0,0]}}\n]}\n");

        SceneFileException error = assertThrows(SceneFileException.class, () -> SceneFileReader.read(file));

        assertTrue(error.getMessage().startsWith(file + ":2:"), error.getMessage());
        assertTrue(error.getMessage().contains("expected an integer but found the end of an array"), error.getMessage());
    }

    @Test
    void theWriterRefusesAnObjectWhoseCellOrKindTheFileCouldNotCarry() {
        SeenObject misplaced = new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, 2.7, -5,
                Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, grid.cell(30, -5));
        SeenObject misnamed = SeenObject.simple(ObjectKind.FLAG, "b", Relation.NONE, 2.7, -5, grid);
        for (SeenObject object : List.of(misplaced, misnamed)) {
            Path file = dir.resolve("refused.json");
            Scene scene = new Scene(1, SceneFixtures.OBSERVER, List.of(object), List.of(Action.turn(1)));

            IllegalArgumentException error = assertThrows(IllegalArgumentException.class,
                    () -> SceneFileWriter.write(file, new SceneFile(header, List.of(scene))));

            assertTrue(error.getMessage().startsWith("cannot write object 'b'"), error.getMessage());
            assertTrue(Files.notExists(file), "nothing written");
        }
    }

    @Test
    void worldPlayersWithoutNumberOrPositionRoundTrip() throws IOException {
        World world = new World(1, 2, 3, 0, 0, 0, 8000, 1, 0, Double.NaN, Double.NaN, Double.NaN, Double.NaN, -1,
                List.of(new World.Player(Relation.UNKNOWN, 0, Double.NaN, Double.NaN, 3)), "play_on", 0, 1);
        Scene scene = new Scene(4, SceneFixtures.OBSERVER, List.of(), List.of(Action.dash(60)), null, 0, world);
        Path file = dir.resolve("world.json");
        SceneFileWriter.write(file, new SceneFile(header, List.of(scene)));

        assertTrue(Files.readString(file).contains("\"players\":[[\"unknown\",null,null,null,3]]"), Files.readString(file));
        assertEquals(List.of(scene), SceneFileReader.read(file).scenes());
    }
}
