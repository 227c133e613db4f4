package org.scenes.internal.convert;

import java.io.IOException;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/**
 * When synchronous sees fall: each player's {@link SynchSeeCounter}, from its init on, moved by
 * what it sent ({@code synch_see}, {@code change_view}) and run through each show's step on the
 * reading thread. The workers learn the outcome from {@link RebuildStep#synchSees()}.
 */
final class SynchSees {
    /** Each player's counter, by TEAM_UNUM. */
    private final Map<String, SynchSeeCounter> counters = new HashMap<>();
    private final StepClock clock;
    private final GameParameters parameters;
    private final PlayerSlots slots;

    SynchSees(StepClock clock, GameParameters parameters, PlayerSlots slots) {
        this.clock = clock;
        this.parameters = parameters;
        this.slots = slots;
    }

    /**
     * The players of this show who get a synchronous see with it: their counters raised
     * through the show's step, the last step's interval the show's view width.
     */
    Set<RebuiltPlayer> due(GameFrame frame) {
        Set<RebuiltPlayer> due = null;
        long at = clock.serverStep();
        for (PlayerState state : frame.players()) {
            RebuiltPlayer player = slots.of(state);
            SynchSeeCounter counter = player == null ? null : counters.get(player.key);
            if (counter == null || !counter.synch()) {
                continue; // (the worker's RebuiltPlayer.synchSee is its own)
            }
            counter.interval(at - 1, (int) Math.max(1, Math.round(state.viewWidth() / parameters.visibleAngle * 1.5)));
            if (counter.advance(at)) {
                due = due == null ? new HashSet<>() : due;
                due.add(player);
            }
        }
        return due == null ? Set.of() : due;
    }

    /** The player's init arrived in the server's step {@code at}. */
    void init(String key, long at, boolean synch) {
        counters.put(key, new SynchSeeCounter(at, 2, synch));
    }

    /** A player synchronous without an init or {@code synch_see} in the command log: from the server's step 0. */
    void synchFromStart(String key) {
        counter(key, true).startSynch(0);
    }

    /** The player's counter from its init (the server's step 0 when the command log has none). */
    private SynchSeeCounter counter(String key, boolean synch) {
        return counters.computeIfAbsent(key, k -> new SynchSeeCounter(0, 2, synch));
    }

    /** What a player's message does to its see counter: {@code synch_see}, {@code change_view}. */
    void sent(String key, String message, CommandLogReader.Entry entry) throws IOException {
        if (message.startsWith("(synch_see)")) {
            counter(key, false).startSynch(clock.serverStep(entry));
            return;
        }
        for (int at = message.indexOf("(change_view "); at >= 0; at = message.indexOf("(change_view ", at + 1)) {
            int end = message.indexOf(')', at);
            String[] words = message.substring(at + 13, end < 0 ? message.length() : end).strip().split("\\s+");
            SynchSeeCounter counter = counter(key, false);
            int interval = SynchSeeCounter.interval(words[0]);
            // synchronous sees are of high quality only: the server ignores a change to low
            boolean ignored = words.length > 2 || counter.synch() && words.length == 2 && !words[1].equals("high");
            if (interval > 0 && !ignored) {
                counter.interval(clock.serverStep(entry), interval);
            }
        }
    }
}
