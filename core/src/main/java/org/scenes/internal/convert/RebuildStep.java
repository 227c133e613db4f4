package org.scenes.internal.convert;

import java.util.List;
import java.util.Set;
import org.scenes.internal.gamelog.GameFrame;

/**
 * One show and what was sent around it, handed to every worker.
 *
 * @param before what the players sent in the steps before the show's
 * @param at what they sent in the show's step, after its see
 * @param seesDue whether the show's sees go out (not after the game is over)
 * @param players the players whose first show this is
 * @param synchSees the players who get a synchronous see with the show
 * @param commandsCover whether the command log reaches this show (else nothing to check against)
 */
record RebuildStep(GameFrame frame, long index, List<Sent> before, List<Sent> at, boolean seesDue,
                   List<RebuiltPlayer> players, Set<RebuiltPlayer> synchSees, boolean commandsCover) {

    /** Tells a worker's thread to stop. */
    static final RebuildStep END = new RebuildStep(null, 0, List.of(), List.of(), false, List.of(), Set.of(), false);

    /** What was sent after the last show. */
    static RebuildStep after(List<Sent> sent) {
        return new RebuildStep(null, 0, sent, List.of(), false, List.of(), Set.of(), false);
    }

    /** What a player sent, for its worker. */
    record Sent(RebuiltPlayer player, String message) {
    }
}
