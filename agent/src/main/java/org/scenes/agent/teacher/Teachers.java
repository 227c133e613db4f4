package org.scenes.agent.teacher;

import java.util.Map;
import java.util.TreeMap;
import org.scenes.agent.BrainFactory;

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

    public static java.util.Set<String> names() {
        return BY_NAME.keySet();
    }
}
