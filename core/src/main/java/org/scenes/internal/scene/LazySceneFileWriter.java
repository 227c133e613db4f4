package org.scenes.internal.scene;

import java.io.IOException;
import java.nio.file.Path;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.Scene;

/**
 * A scene file opened at its first scene, so the header names the observer that the log's init
 * exchange revealed; a log without scenes still gets a valid, empty file at {@link #commit()}.
 * Like {@link SceneFileWriter}, nothing appears at the target until the commit.
 */
public final class LazySceneFileWriter implements AutoCloseable {
    private final Path target;
    private final Grid grid;
    private final String source;
    private SceneFileWriter writer;
    private boolean goalie;

    /** @param source the name of the log the scenes come from, for the header */
    public LazySceneFileWriter(Path target, Grid grid, String source) {
        this.target = target;
        this.grid = grid;
        this.source = source;
    }

    /**
     * Marks the player as its team's goalie in the header. After the first scene the header
     * (which describes the file's first player) is written: a later player's role is not its own.
     */
    public void goalie() {
        if (writer == null) {
            goalie = true;
        }
    }

    public void write(Scene scene) throws IOException {
        if (writer == null) {
            open(scene.observer());
        }
        writer.write(scene);
    }

    private void open(Observer observer) throws IOException {
        writer = SceneFileWriter.create(target, SceneFileHeader.of(grid, new SceneSource(source, observer, goalie)));
    }

    /** Completes the file (an empty one with an unknown observer when no scene came). */
    public void commit() throws IOException {
        if (writer == null) {
            open(Observer.UNKNOWN);
        }
        writer.commit();
    }

    @Override
    public void close() throws IOException {
        if (writer != null) {
            writer.close();
        }
    }
}
