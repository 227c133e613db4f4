package org.scenes.internal.scene;

import org.scenes.api.Observer;

/**
 * Where the scenes of a file came from.
 *
 * @param log the log file name the scenes were converted from (empty when made otherwise)
 * @param observer the player who was logged
 * @param goalie whether that player played as its team's goalie (its init said {@code (goalie)},
 *               or the game log marks it); false when not known
 */
public record SceneSource(String log, Observer observer, boolean goalie) {
    public SceneSource {
        log = log == null ? "" : log;
        observer = observer == null ? Observer.UNKNOWN : observer;
    }

    /** A source whose player is not known to be the goalie. */
    public SceneSource(String log, Observer observer) {
        this(log, observer, false);
    }
}
