package org.scenes.internal.validate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.World;

/** Target replay's dashes leave the stamina above the level where the server cuts the effort. */
class StaminaSafeDashTest {
    private static World withStamina(double stamina) {
        return new World(0, 0, 0, 0, 0, 0, stamina, 1, 0, 5, 5, 0, 0, 0, List.of(), "play_on", 0, 0);
    }

    @Test
    void aDashLeavesTheStaminaAboveTheFloor() {
        assertEquals(100, Validator.staminaSafe(100, withStamina(8000)), 1e-9, "rested: the neighbours' power");
        assertEquals(50, Validator.staminaSafe(100, withStamina(Validator.STAMINA_FLOOR + 50)), 1e-9);
        assertEquals(0, Validator.staminaSafe(100, withStamina(2000)), 1e-9, "below the floor: no dash forward");
        assertEquals(-30, Validator.staminaSafe(-30, withStamina(2000)), 1e-9, "a backward dash is no larger for it");
    }

    @Test
    void withoutAPowerOrAStaminaItChangesNothingUnlessTired() {
        assertEquals(Double.NaN, Validator.staminaSafe(Double.NaN, withStamina(8000)));
        assertEquals(20, Validator.staminaSafe(Double.NaN, withStamina(Validator.STAMINA_FLOOR + 20)), 1e-9);
        assertEquals(100, Validator.staminaSafe(100, withStamina(Double.NaN)), 1e-9);
        assertEquals(100, Validator.staminaSafe(100, null), 1e-9);
    }
}
