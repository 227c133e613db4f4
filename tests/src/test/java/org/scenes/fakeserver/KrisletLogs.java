package org.scenes.fakeserver;

import java.nio.file.Path;
import org.scenes.testing.SharedData;
import org.scenes.tests.SimulatedGame;

/** The log of Carleton player 1: recorded (skipping the test without the shared recordings) or simulated. */
final class KrisletLogs {
    private KrisletLogs() {
    }

    static Path carleton1(String game) {
        switch (game) {
            case "recorded" -> {
                SharedData.assumePresent();
                return SharedData.resolve("krislet/classic-game1/Carleton_1.lsf.gz");
            }
            case "simulated" -> {
                return SimulatedGame.log("Carleton", 1);
            }
            default -> throw new IllegalArgumentException("recorded or simulated, not " + game);
        }
    }
}
