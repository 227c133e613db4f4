package org.scenes.internal.scene;

import java.util.Locale;

/**
 * The ranges of the numbers a scene file may hold: what the soccer server can send, with room to
 * spare. A number outside them (or not finite) is a broken file, never a value to match on: a
 * metric given 1e308 or NaN ranks scenes by nonsense.
 */
final class SceneValues {
    /** Metres: the pitch's diagonal with its surroundings is about 130 m. */
    static final double MAX_DISTANCE = 1000;
    /** Degrees: the server sends directions from -180 to 180. */
    static final double MAX_DIRECTION = 180;
    /** Per-cycle changes of distance (m) or direction (deg). */
    static final double MAX_CHANGE = 10_000;
    /**
     * Objects in one scene: a see lists at most the 55 flags, 10 lines, 2 goals, the ball and 22
     * players; matching costs grow with the square of the count, so a larger scene is refused.
     */
    static final int MAX_OBJECTS = 256;
    /** Action parameters: powers, moments, directions and coordinates. */
    static final double MAX_PARAMETER = 10_000;

    private SceneValues() {
    }

    static String format(double value) {
        return value == Math.rint(value) ? String.format(Locale.ROOT, "%.0f", value) : Double.toString(value);
    }
}
