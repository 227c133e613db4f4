package org.scenes.internal.inference;

import java.util.HashMap;
import java.util.Map;
import org.scenes.internal.protocol.AnnouncedParameters;
import org.scenes.internal.protocol.Parameters;
import org.scenes.internal.world.ServerDefaults;

/**
 * The server's parameters the command models need, from a game log's {@code server_param} and
 * {@code player_type} lines; rcssserver 19's defaults where a log has none.
 */
final class ServerModel {
    /** One heterogeneous player type's parameters. */
    record PlayerType(double decay, double inertiaMoment, double dashPowerRate, double staminaIncMax,
                      double playerSize, double kickableMargin, double kickPowerRate, double kickRand,
                      double extraStamina, double speedMax) {
    }

    private final AnnouncedParameters announced = new AnnouncedParameters();
    private final Map<Integer, PlayerType> types = new HashMap<>();

    /** Takes a {@code server_param}, {@code player_param} or {@code player_type} line. */
    void parameters(String line) {
        Parameters params = announced.read(line);
        if (params != null && params.head().equals("player_type") && params.named().containsKey("id")) {
            types.put((int) params.number("id"), type(params.named()));
        }
    }

    double get(String name, double fallback) {
        return announced.server(name, fallback);
    }

    /** The player type's parameters; the default type's (server_param's) when the log has none. */
    PlayerType type(int id) {
        PlayerType type = types.get(id);
        return type != null ? type : type(Map.of());
    }

    private PlayerType type(Map<String, String> named) {
        return new PlayerType(num(named, "player_decay", get("player_decay", ServerDefaults.PLAYER_DECAY)),
                num(named, "inertia_moment", get("inertia_moment", ServerDefaults.INERTIA_MOMENT)),
                num(named, "dash_power_rate", get("dash_power_rate", 0.006)),
                num(named, "stamina_inc_max", get("stamina_inc_max", 45)),
                num(named, "player_size", get("player_size", ServerDefaults.PLAYER_SIZE)),
                num(named, "kickable_margin", get("kickable_margin", ServerDefaults.KICKABLE_MARGIN)),
                num(named, "kick_power_rate", get("kick_power_rate", ServerDefaults.KICK_POWER_RATE)),
                num(named, "kick_rand", get("kick_rand", 0.1)),
                num(named, "extra_stamina", get("extra_stamina", 50)),
                num(named, "player_speed_max", get("player_speed_max", 1.05)));
    }

    private static double num(Map<String, String> named, String name, double fallback) {
        return Parameters.number(named, name, fallback);
    }
}
