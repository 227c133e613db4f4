package org.scenes.match;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.scenes.scene.Grid;
import org.scenes.scene.Scene;
import org.scenes.scene.SceneFile;
import org.scenes.scene.SceneFileReader;

/**
 * The stored scenes a recognizer searches, built once and never changed. All scenes share one
 * grid: cells of different grids cannot be compared, so mixing them is refused.
 */
public final class KnowledgeBase {
    private final Grid grid;
    private final List<Scene> scenes;

    private KnowledgeBase(Grid grid, List<Scene> scenes) {
        this.grid = grid;
        this.scenes = List.copyOf(scenes);
    }

    public static KnowledgeBase of(Grid grid, List<Scene> scenes) {
        return new KnowledgeBase(grid, scenes);
    }

    /**
     * Scenes of several files, each file passed through fresh transforms (made by
     * {@code transforms}) in order, since transforms such as memory follow one player's sequence.
     */
    public static KnowledgeBase fromFiles(List<SceneFile> files, Supplier<List<SceneTransform>> transforms) {
        if (files.isEmpty()) {
            throw new IllegalArgumentException("a knowledge base needs at least one scene file");
        }
        Grid grid = files.get(0).grid();
        List<Scene> scenes = new ArrayList<>();
        for (SceneFile file : files) {
            if (!file.grid().equals(grid)) {
                throw new IllegalArgumentException("scene files use different grids (" + grid.describe() + " and "
                        + file.grid().describe() + " from " + file.header().source().log()
                        + "); convert them with the same --grid and --bounds");
            }
            scenes.addAll(transform(file.scenes(), transforms.get()));
        }
        return new KnowledgeBase(grid, scenes);
    }

    /** Reads the files (gzip or plain) and builds the knowledge base; errors name the file. */
    public static KnowledgeBase load(List<Path> paths, Supplier<List<SceneTransform>> transforms) {
        List<SceneFile> files = new ArrayList<>();
        for (Path path : paths) {
            SceneFile file = SceneFileReader.read(path);
            if (!files.isEmpty() && !file.grid().equals(files.get(0).grid())) {
                throw new IllegalArgumentException(path + ": grid " + file.grid().describe() + " differs from "
                        + files.get(0).grid().describe() + " of " + paths.get(0) + "; convert them with the same grid");
            }
            files.add(file);
        }
        return fromFiles(files, transforms);
    }

    /** One player's scenes through fresh transforms, in order. */
    public static List<Scene> transform(List<Scene> scenes, List<SceneTransform> transforms) {
        if (transforms.isEmpty()) {
            return scenes;
        }
        List<Scene> out = new ArrayList<>(scenes.size());
        for (Scene scene : scenes) {
            Scene current = scene;
            for (SceneTransform transform : transforms) {
                current = transform.apply(current);
            }
            out.add(current);
        }
        return out;
    }

    public Grid grid() {
        return grid;
    }

    public List<Scene> scenes() {
        return scenes;
    }

    public int size() {
        return scenes.size();
    }

    public Scene scene(int index) {
        return scenes.get(index);
    }
}
