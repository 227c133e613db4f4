package org.scenes.simulator.teacher;

import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import org.scenes.api.Side;
import org.scenes.internal.protocol.See;
import org.scenes.simulator.BrainFactory;

/** The teacher agents by name, as {@code scenes simulate --teams NAME:N,...} names them. */
public final class Teachers {
    private static final Map<String, BrainFactory> BY_NAME = new TreeMap<>(Map.of(
            "krislet", (team, random) -> new Krislet(random),
            "statebased", (team, random) -> new StateBasedKrislet(random)));

    private Teachers() {
    }

    /** The factory for a teacher name; an unknown name lists the known ones. */
    public static BrainFactory byName(String name) {
        BrainFactory factory = BY_NAME.get(name);
        if (factory == null) {
            throw new IllegalArgumentException("unknown teacher '" + name + "'; available: "
                    + String.join(", ", BY_NAME.keySet()));
        }
        return factory;
    }

    public static Set<String> names() {
        return BY_NAME.keySet();
    }

    /**
     * The command the classic Krislet answers {@code see} with when playing on {@code side}, e.g.
     * {@code (dash 90.0)}: its rules without its clock, for labelling scenes made without a game.
     */
    public static String krisletCommand(See see, Side side) {
        return Krislet.decide(see, side);
    }
}
