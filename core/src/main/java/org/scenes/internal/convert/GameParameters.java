package org.scenes.internal.convert;

import java.util.HashMap;
import java.util.Map;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.Parameters;
import org.scenes.internal.vision.VisionParams;

/**
 * The server's parameters a game log holds ({@code server_param}, {@code player_type}): what the
 * rebuilt sees and the see clocks need. Written by the reading thread before the first show,
 * read by the workers after.
 */
final class GameParameters {
    private final MessageParser parser = new MessageParser();
    private final Map<String, String> serverParam = new HashMap<>();
    private final Map<Integer, Map<String, String>> playerTypes = new HashMap<>();
    double visibleAngle = 90;
    double sendStep = 150;
    double simulatorStep = 100;
    double visibleDistance = 3;

    /** Takes in a parameter line of the game log; other lines are ignored. */
    void read(String line) {
        Message message = parser.parse(line);
        if (!(message instanceof Parameters params)) {
            return;
        }
        if (params.head().equals("server_param")) {
            serverParam.putAll(params.named());
            visibleAngle = number(params, "visible_angle", visibleAngle);
            sendStep = number(params, "send_step", sendStep);
            simulatorStep = number(params, "simulator_step", simulatorStep);
            visibleDistance = number(params, "visible_distance", visibleDistance);
        } else if (params.head().equals("player_type") && params.named().containsKey("id")) {
            playerTypes.put((int) params.number("id"), params.named());
        }
    }

    private static double number(Parameters params, String name, double fallback) {
        double value = params.number(name);
        return Double.isNaN(value) ? fallback : value;
    }

    /** The vision of a player of this heterogeneous type; clients before version 18 see with the defaults. */
    VisionParams vision(int type, int version) {
        return VisionParams.of(serverParam, version >= 18 ? playerTypes.get(type) : null);
    }

    /** The period of a player's asynchronous sees in its view mode, in ms. */
    double period(PlayerState state) {
        return sendStep * state.viewWidth() / visibleAngle * (state.viewQuality() == 'h' ? 1 : 0.5);
    }
}
