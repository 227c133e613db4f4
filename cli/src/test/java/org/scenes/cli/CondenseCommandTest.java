package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

class CondenseCommandTest {
    private final CommandRunner cli = new CommandRunner();

    /** A player that turns to a ball out of the middle, dashes to it otherwise, kicks when it is near. */
    private static Path scenes(Path dir) throws IOException {
        Random random = new Random(5);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < 400; i++) {
            double direction = random.nextInt(81) - 40;
            double distance = 0.5 + random.nextInt(30);
            Action action = distance < 1 ? Action.kick(100, 0)
                    : Math.abs(direction) > 20 ? Action.turn(direction) : Action.dash(80);
            scenes.add(new Scene(i, Observer.UNKNOWN,
                    List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT)),
                    List.of(action)));
        }
        Path file = dir.resolve("player.json");
        SceneFileWriter.write(file, new SceneFile(SceneFileHeader.of(Grid.DEFAULT, new SceneSource("", null)), scenes));
        return file;
    }

    @Test
    void condenseWritesFewerScenesThatPredictTheWholeFileAsWell(@TempDir Path dir) throws IOException {
        Path file = scenes(dir);
        Path condensed = dir.resolve("condensed.json.gz");
        assertEquals(ExitCodes.OK, cli.run("condense", "--train", file, "--metric", "ball-goal", "-o", condensed), cli.err());
        assertTrue(cli.out().contains("Kept"), cli.out());
        int kept = SceneFileReader.read(condensed).scenes().size();
        assertTrue(kept > 0 && kept < 200, "kept " + kept + " of 400");
        assertEquals(ExitCodes.OK, cli.run("validate", "--train", condensed, "--test", file, "--metric", "ball-goal"), cli.err());
        assertTrue(cli.out().contains("Action accuracy"), cli.out());
        assertEquals(ExitCodes.OK, cli.run("show", file, "--key-scenes", "2", "--metric", "ball-goal"), cli.err());
        assertTrue(cli.out().contains("influence"), cli.out());
        assertEquals(ExitCodes.USAGE, cli.run("condense", "--train", file, "-o", dir.resolve("x.json"), "--edit-k", "-2"));
        assertTrue(cli.err().contains("--edit-k"), cli.err());
        assertTrue(Files.notExists(dir.resolve("x.json")), "nothing written on a usage error");
    }

    @Test
    void exportWritesTheKeyScenesShowPicksInTheFilesOrder(@TempDir Path dir) throws IOException {
        Path file = scenes(dir);
        assertEquals(ExitCodes.OK, cli.run("show", file, "--key-scenes", "3", "--metric", "ball-goal"), cli.err());
        List<String> shown = new ArrayList<>();
        java.util.regex.Matcher cycles = java.util.regex.Pattern.compile("Scene cycle (\\d+)").matcher(cli.out());
        while (cycles.find()) {
            shown.add(cycles.group(1));
        }
        assertTrue(shown.size() >= 2, cli.out());
        Path table = dir.resolve("key.csv");
        assertEquals(ExitCodes.OK, cli.run("export", "--format", "csv", file, "--key-scenes", "3", "--metric", "ball-goal",
                "-o", table), cli.err());
        List<String> lines = Files.readAllLines(table);
        assertTrue(lines.get(0).endsWith(",influence,action"), lines.get(0));
        List<String> exported = lines.subList(1, lines.size()).stream().map(line -> line.split(",")[0]).toList();
        assertEquals(shown.stream().sorted(java.util.Comparator.comparingInt(Integer::parseInt)).toList(), exported,
                "the same scenes, in the file's order");
        assertEquals(ExitCodes.USAGE, cli.run("export", "--format", "csv", file, "--key-scenes", "0", "-o", dir.resolve("y.csv")));
        assertTrue(cli.err().contains("--key-scenes"), cli.err());
        assertTrue(Files.notExists(dir.resolve("y.csv")), "nothing written on a usage error");
    }
}
