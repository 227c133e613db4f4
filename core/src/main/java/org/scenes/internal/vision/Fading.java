package org.scenes.internal.vision;

import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Whether a detail that fades with distance (a player's team or number, an object's changes) is
 * shown: always below the far length, never from the too-far length on, in between with a
 * probability falling linearly ({@link #dice}), as the server decides, or below the halfway point
 * ({@link #HALFWAY}), as this project's simulator decides.
 */
public interface Fading {
    /** Whether the detail is shown at {@code distance} (the seen, quantised distance). */
    boolean shown(double distance, double farLength, double tooFarLength);

    /** The fading of one observer's sees: dice of its own, so observers can be rebuilt apart. */
    Fading forObserver(String name);

    /** The simulator's rule: shown below the halfway point between far and too far. */
    Fading HALFWAY = new Fading() {
        @Override
        public boolean shown(double distance, double far, double tooFar) {
            return distance < (far + tooFar) / 2;
        }

        @Override
        public Fading forObserver(String name) {
            return this;
        }
    };

    /** The server's rule, with dice drawn from a generator seeded with {@code seed}. */
    static Fading dice(long seed) {
        return new Fading() {
            private final SplittableRandom random = new SplittableRandom(seed);

            @Override
            public boolean shown(double distance, double far, double tooFar) {
                double hidden = (distance - far) / (tooFar - far);
                if (hidden >= 1) {
                    return false;
                }
                if (!(hidden > 0)) {
                    return true; // below far; also far == too far, as version 18 player types have for teams
                }
                return random.nextDouble() >= hidden;
            }

            @Override
            public Fading forObserver(String name) {
                return dice(seed * 1_000_003L + name.hashCode());
            }
        };
    }

    /** {@code halfway} or {@code dice}, the names options use; null for another. */
    static Fading named(String name, long seed) {
        return switch (name.toLowerCase(Locale.ROOT)) {
            case "halfway" -> HALFWAY;
            case "dice" -> dice(seed);
            default -> null;
        };
    }
}
