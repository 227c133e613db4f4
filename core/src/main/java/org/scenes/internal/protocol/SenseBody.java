package org.scenes.internal.protocol;

import java.util.List;
import java.util.Map;

/**
 * {@code (sense_body TIME ...)}: the player's own state. The fields every version sends are typed;
 * the command counters are in {@link Counts}; the structured extras of newer versions
 * ({@code arm}, {@code focus}, {@code tackle}, {@code collision}, {@code foul}, {@code focus_point})
 * are in {@link #details()} under dotted keys such as {@code arm.target} or {@code foul.card},
 * values as sent (e.g. {@code "0 0"}). Numbers not sent are {@code NaN}.
 */
public record SenseBody(int time, String viewQuality, String viewWidth, double stamina, double effort,
                        double capacity, double speed, double speedDirection, double headAngle,
                        Counts counts, Map<String, String> details, List<String> leftovers)
        implements Message {

    public SenseBody {
        details = Map.copyOf(details);
        leftovers = List.copyOf(leftovers);
    }

    /** How many of each command the server has executed so far; -1 for a counter not sent. */
    public record Counts(int kick, int dash, int turn, int say, int turnNeck, int catches, int move,
                         int changeView, int changeFocus) {
        static final Counts NONE = new Counts(-1, -1, -1, -1, -1, -1, -1, -1, -1);
    }

    @Override
    public String head() {
        return "sense_body";
    }
}
