package org.scenes.internal.scene;

import org.scenes.api.Observer;

/**
 * Where the scenes of a file came from.
 *
 * @param log the log file name the scenes were converted from (empty when made otherwise)
 * @param observer the player who was logged
 */
public record SceneSource(String log, Observer observer) {
    public SceneSource {
        log = log == null ? "" : log;
        observer = observer == null ? Observer.UNKNOWN : observer;
    }
}
