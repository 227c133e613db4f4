package org.scenes.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

/** Scene files for the services' tests. */
public final class TestFiles {
    private TestFiles() {
    }

    /** Krislet-like scenes: with the ball far at direction 0 a dash, elsewhere a turn, near it a kick. */
    public static Path krislet(Path path, long seed, int count) throws Exception {
        Observer observer = new Observer("Test", Side.LEFT, 1);
        Random random = new Random(seed);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            double distance = random.nextInt(10) == 0 ? 0.5 : 2 + random.nextInt(40);
            double direction = random.nextInt(3) == 0 ? 0 : random.nextInt(61) - 30;
            double goal = random.nextInt(41) - 20;
            Action action = distance <= 1 ? Action.kick(100, goal) : direction == 0 ? Action.dash(10 * distance)
                    : Action.turn(direction);
            scenes.add(new Scene(i, observer, List.of(
                    SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT),
                    SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, 40, goal, Grid.DEFAULT)), List.of(action)));
        }
        String name = path.getFileName().toString();
        SceneFileWriter.write(path, new SceneFile(SceneFileHeader.of(Grid.DEFAULT, new SceneSource(name, observer)), scenes));
        return path;
    }
}
