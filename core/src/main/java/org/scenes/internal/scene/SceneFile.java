package org.scenes.internal.scene;

import java.util.List;
import org.scenes.api.Grid;
import org.scenes.api.Scene;

/** A whole scene file held in memory: its header and scenes. */
public record SceneFile(SceneFileHeader header, List<Scene> scenes) {
    public SceneFile {
        scenes = List.copyOf(scenes);
    }

    public Grid grid() {
        return header.grid();
    }

    /** {@link Grid#common(List, List)} over scene files held in memory, each known by its source log. */
    public static Grid commonGrid(List<SceneFile> files) {
        return Grid.common(files.stream().map(f -> f.header().source().log()).toList(),
                files.stream().map(SceneFile::grid).toList());
    }
}
