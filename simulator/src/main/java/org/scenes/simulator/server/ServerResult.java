package org.scenes.simulator.server;

import java.nio.file.Path;
import java.util.List;

/**
 * How a served game ended.
 *
 * @param cycles the game clock at the end
 * @param steps server steps run, including pauses with the clock stopped
 * @param players players that connected
 * @param dropped players dropped for not answering in time (synchronous mode)
 * @param stopped whether the game was stopped before time over (Ctrl-C, SIGTERM, {@link SoccerServer#stop})
 * @param latenessP50Millis real-time mode: the median of how late cycles started, ms
 * @param latenessP99Millis real-time mode: the 99th percentile of how late cycles started, ms
 * @param latenessMaxMillis real-time mode: the latest cycle start, ms
 * @param seconds wall-clock time from kick-off preparations to the end
 * @param logs the game log and command log written, if any
 */
public record ServerResult(int scoreLeft, int scoreRight, int cycles, int steps, int players, int dropped,
                           boolean stopped, double latenessP50Millis, double latenessP99Millis,
                           double latenessMaxMillis, double seconds, List<Path> logs) {
    public ServerResult {
        logs = List.copyOf(logs);
    }
}
