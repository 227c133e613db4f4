package org.scenes.internal.convert;

import org.scenes.api.Side;
import org.scenes.internal.gamelog.PlayerState;

/**
 * The rebuilt players by show slot (side, number), for the workers: a slot is set by the reading
 * thread before a step showing its player is handed out.
 */
final class PlayerSlots {
    private final RebuiltPlayer[][] slots = new RebuiltPlayer[2][64];

    /** The rebuilt player a show's state is of, or null (not on the field, or not converted). */
    RebuiltPlayer of(PlayerState state) {
        if (state.state() == 0 || state.unum() < 0 || state.unum() >= 64) {
            return null;
        }
        return slots[state.side() == Side.LEFT ? 0 : 1][state.unum()];
    }

    void put(PlayerState state, RebuiltPlayer player) {
        if (state.unum() >= 0 && state.unum() < 64) {
            slots[state.side() == Side.LEFT ? 0 : 1][state.unum()] = player;
        }
    }
}
