package org.scenes.app;

import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.teacher.Teachers;

/** The built-in teachers' teams as the commands spell them, for the workflows that play games. */
public final class Teams {
    private Teams() {
    }

    /**
     * The team {@code name} of a built-in teacher, spelt {@code TEACHER:N} ({@code krislet:5}).
     *
     * @throws RequestException for another spelling, an unknown teacher or a number of players a team cannot have
     */
    public static GameSetup.Team builtIn(String spec, String name) {
        String[] parts = spec.trim().split(":", -1);
        if (parts.length != 2) {
            throw new RequestException("--teams: '" + spec + "' is not TEACHER:N, e.g. krislet:5");
        }
        BrainFactory brains;
        int players;
        try {
            brains = Teachers.byName(parts[0]);
            players = Integer.parseInt(parts[1]);
        } catch (NumberFormatException e) {
            throw new RequestException("--teams: '" + parts[1] + "' in '" + spec + "' is not a number of players");
        } catch (IllegalArgumentException e) {
            throw new RequestException("--teams: " + e.getMessage());
        }
        try {
            return new GameSetup.Team(name, players, brains);
        } catch (IllegalArgumentException e) {
            throw new RequestException("--teams/--names: " + e.getMessage());
        }
    }
}
