package org.scenes.protocol;

import java.util.List;
import java.util.Map;

/**
 * {@code (sense_body TIME ...)}: the player's own state. The fields every version sends are typed;
 * the command counters ({@code kick}, {@code dash}, ... {@code change_focus}) are in {@link #counts()},
 * and the structured extras of newer versions ({@code arm}, {@code focus}, {@code tackle},
 * {@code collision}, {@code foul}, {@code focus_point}) in {@link #details()} under dotted keys
 * such as {@code arm.target} or {@code foul.card}, values as sent.
 */
public record SenseBody(int time, String viewQuality, String viewWidth, double stamina, double effort,
                        double capacity, double speed, double speedDirection, double headAngle,
                        Map<String, Integer> counts, Map<String, String> details, List<String> leftovers)
        implements Message {

    public SenseBody {
        counts = Map.copyOf(counts);
        details = Map.copyOf(details);
        leftovers = List.copyOf(leftovers);
    }

    @Override
    public String head() {
        return "sense_body";
    }
}
