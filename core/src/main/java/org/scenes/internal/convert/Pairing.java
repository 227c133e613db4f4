package org.scenes.internal.convert;

import java.util.Locale;

/** How a log's sees and actions become scenes (docs/conversion.md, "Scenes"). */
public enum Pairing {
    /** A scene per distinct {@code see}: the classic rule, for players that act after each see. */
    SEE,
    /**
     * A scene per cycle (from one {@code sense_body} to the next) showing the latest {@code see}, with
     * its age: for players that act every cycle while a see comes every other cycle (synchronous vision).
     */
    CYCLE,
    /** {@link #CYCLE} from the server's {@code (ok synch_see)} on, {@link #SEE} until then. */
    AUTO;

    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The pairing with this key ({@code see}, {@code cycle}, {@code auto}), or null. */
    public static Pairing fromKey(String key) {
        for (Pairing pairing : values()) {
            if (pairing.key().equals(key)) {
                return pairing;
            }
        }
        return null;
    }
}
