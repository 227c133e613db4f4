package org.scenes.options;

import picocli.CommandLine.Option;

/** {@code --world} / {@code --no-world}: whether converted scenes carry the player's world model. */
public final class WorldOptions {
    @Option(names = "--world", negatable = true, defaultValue = "true", fallbackValue = "true",
            description = "Give each scene the player's world model (its position, the ball's, the players it"
                    + " remembers, stamina, play mode, score; the world block of docs/scene-format.md): what the field"
                    + " metric, --replay target and the shipped configurations need. --no-world leaves it out"
                    + " (HELIOS base's files about half the size). Default: on.")
    private boolean world = true;

    public boolean world() {
        return world;
    }
}
