package org.scenes.internal.convert;

import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.AnnouncedParameters;
import org.scenes.internal.protocol.Parameters;
import org.scenes.internal.vision.VisionParams;

/**
 * The server's parameters a game log holds ({@code server_param}, {@code player_type}): what the
 * rebuilt sees and the see clocks need. Written by the reading thread before the first show,
 * read by the workers after.
 */
final class GameParameters {
    private final AnnouncedParameters announced = new AnnouncedParameters();
    double visibleAngle = 90;
    double sendStep = 150;
    double simulatorStep = 100;
    double visibleDistance = 3;

    /** Takes in a parameter line of the game log; other lines are ignored. */
    void read(String line) {
        Parameters params = announced.read(line);
        if (params != null && params.head().equals("server_param")) {
            // kept as fields: period() is asked at every see of every player
            visibleAngle = announced.server("visible_angle", visibleAngle);
            sendStep = announced.server("send_step", sendStep);
            simulatorStep = announced.server("simulator_step", simulatorStep);
            visibleDistance = announced.server("visible_distance", visibleDistance);
        }
    }

    /** The vision of a player of this heterogeneous type; clients before version 18 see with the defaults. */
    VisionParams vision(int type, int version) {
        return VisionParams.of(announced.server(), version >= 18 ? announced.playerType(type) : null);
    }

    /** The period of a player's asynchronous sees in its view mode, in ms. */
    double period(PlayerState state) {
        return sendStep * state.viewWidth() / visibleAngle * (state.viewQuality() == 'h' ? 1 : 0.5);
    }
}
