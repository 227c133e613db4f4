package org.scenes.scene;

import java.util.List;

/** A whole scene file held in memory: its header and scenes. */
public record SceneFile(SceneFileHeader header, List<Scene> scenes) {
    public SceneFile {
        scenes = List.copyOf(scenes);
    }

    public Grid grid() {
        return header.grid();
    }
}
