package org.scenes.internal.convert;

import java.util.Locale;

/** Why a would-be scene was not written (see docs/conversion.md for the exact rules). */
public enum DropReason {
    /** A {@code see} after which the player sent no scene action before the next different {@code see}. */
    NO_ACTION,
    /** Actions the player sent before its first {@code see} (or after a reconnect, before the next). */
    NO_SEE;

    public String label() {
        return name().toLowerCase(Locale.ROOT).replace('_', ' ');
    }
}
