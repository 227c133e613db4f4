package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

/** The published JSON Schema accepts what the writer writes, and rejects what the reader rejects. */
class SceneSchemaTest {
    private static final Path SCHEMA = Path.of(System.getProperty("scenes.root"), "docs", "scene-file.schema.json");
    private final ObjectMapper mapper = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void writtenFilesConformToTheSchema() throws IOException {
        Grid grid = Grid.DEFAULT;
        Observer observer = new Observer("Carleton", Side.LEFT, 3);
        SeenObject player = new SeenObject(ObjectKind.PLAYER, "p", "University", 7, true, Relation.OPPONENT,
                10.5, -20, 0.2, -1, 45, 30, 12, 'k', grid.cell(10.5, -20));
        List<Scene> scenes = List.of(
                new Scene(3, observer, List.of(player, SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 0.6, 3, grid)),
                        List.of(Action.kick(100, -10), Action.turnNeck(30))),
                new Scene(4, new Observer("University", Side.RIGHT, 1),
                        List.of(SeenObject.simple(ObjectKind.GOAL, "g l", Relation.OWN, 20, 1, grid)), List.of(Action.move(-10, 3))),
                new Scene(5, observer, List.of(), List.of(Action.turn(20)), null, 1,
                        new World(-10.5, 3.25, 45, -30, 0.1, 0, 7000, 0.95, 1, 2.5, -1, 0.8, 0.02, 0,
                                List.of(new World.Player(Relation.OPPONENT, 7, 1, 2, 3),
                                        new World.Player(Relation.UNKNOWN, 0, 5, 6, 0)), "play_on", 1, 0)),
                new Scene(6, observer, List.of(), List.of(Action.turn(20)), null, 0,
                        new World(Double.NaN, Double.NaN, Double.NaN, 0, Double.NaN, Double.NaN, Double.NaN,
                                Double.NaN, -1, Double.NaN, Double.NaN, Double.NaN, Double.NaN, -1, List.of(), "", 0, 0)));
        Path file = dir.resolve("s.json");
        SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(grid, new SceneSource("x.lsf", observer)), scenes));

        Set<ValidationMessage> errors = schema().validate(mapper.readTree(file.toFile()));

        assertEquals(Set.of(), errors);
    }

    @Test
    void theSchemaRejectsAFutureFormatAndAMissingCell() throws IOException {
        JsonNode future = mapper.readTree("{\"format\":4,\"grid\":{\"columns\":5,\"bounds\":[1,5]},\"scenes\":[]}");
        assertFalse(schema().validate(future).isEmpty());
        ObjectNode noCell = (ObjectNode) mapper.readTree("{\"format\":1,\"grid\":{\"columns\":5,\"bounds\":[1,5]},"
                + "\"scenes\":[{\"cycle\":1,\"objects\":[{\"kind\":\"ball\",\"name\":\"b\"}],\"actions\":[]}]}");
        assertFalse(schema().validate(noCell).isEmpty());
    }

    @Test
    void theSchemaChecksFormatThreeObjectArrays() throws IOException {
        String file = "{\"format\":3,\"grid\":{\"columns\":5,\"bounds\":[1,5]},\"scenes\":[{\"cycle\":1,\"objects\":[%s],"
                + "\"actions\":[]}]}";
        assertEquals(Set.of(), schema().validate(mapper.readTree(String.format(file,
                "[\"g l\",20,1,{\"relation\":\"own\"}],[\"f r t\",null,-31],[\"p\",3,4,0,0,10,20,30,{\"team\":\"A\"}]"))));
        for (String wrong : List.of("[\"x\",1,2]", "[\"b\",-1,2]", "[\"b\",1,2,{\"unum\":1},{\"unum\":2}]",
                "[\"p\",1,2,{\"side\":\"l\"}]", "[\"b\",1,2,3,4,5,6,7,8]")) {
            assertFalse(schema().validate(mapper.readTree(String.format(file, wrong))).isEmpty(), wrong);
        }
    }

    private JsonSchema schema() throws IOException {
        return JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V202012)
                .getSchema(Files.readString(SCHEMA));
    }
}
