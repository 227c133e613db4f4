package org.scenes.internal.scene;

import org.scenes.api.Grid;

/**
 * Everything a scene file says before its scenes.
 *
 * @param format the file format version
 * @param grid the grid every object's cell was computed with
 * @param source the log and player the scenes came from
 */
public record SceneFileHeader(int format, Grid grid, SceneSource source) {
    /**
     * The format version this build writes; it reads this and every older one. Version 2 added the
     * optional per-scene {@code world} block (version 1 files read as scenes without it); version 3
     * writes seen objects and the world's players as arrays, without what the name and grid imply.
     */
    public static final int CURRENT_FORMAT = 3;

    public static SceneFileHeader of(Grid grid, SceneSource source) {
        return new SceneFileHeader(CURRENT_FORMAT, grid, source);
    }
}
