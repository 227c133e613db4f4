package org.scenes.internal.vision;

import java.util.Map;
import org.scenes.internal.protocol.Parameters;

/**
 * The parameters of the server's vision model: {@code visible_distance} (objects sensed behind),
 * the quantisation steps of distances ({@code quantize_step} for moving objects,
 * {@code quantize_step_l} for landmarks and lines), and the distances over which a seen player's
 * team and uniform number, and the distance and direction changes of the ball and flags, fade:
 * shown always below the far length, never beyond the too-far length.
 */
public record VisionParams(double visibleDistance, double quantizeStep, double quantizeStepL,
                           double unumFarLength, double unumTooFarLength, double teamFarLength,
                           double teamTooFarLength, double ballVelFarLength, double ballVelTooFarLength,
                           double flagChgFarLength, double flagChgTooFarLength) {
    /**
     * The server's defaults for clients before version 18: players' team fades from 40 to 60 m,
     * number and every change from 20 to 40 m.
     */
    public static final VisionParams DEFAULT = new VisionParams(3, 0.1, 0.01, 20, 40, 40, 60, 20, 40, 20, 40);

    /**
     * The parameters of a game log's {@code server_param} (named pairs) and, for clients of
     * version 18 and later, the fading lengths of the player's {@code player_type}; missing ones keep
     * their default.
     *
     * @param playerType the player type's named parameters, or null for clients before version 18
     */
    public static VisionParams of(Map<String, String> serverParam, Map<String, String> playerType) {
        VisionParams d = DEFAULT;
        double unumFar = number(serverParam, "unum_far_length", d.unumFarLength);
        double unumTooFar = number(serverParam, "unum_too_far_length", d.unumTooFarLength);
        double teamFar = number(serverParam, "team_far_length", d.teamFarLength);
        double teamTooFar = number(serverParam, "team_too_far_length", d.teamTooFarLength);
        double ballFar = unumFar;
        double ballTooFar = unumTooFar;
        double flagFar = unumFar;
        double flagTooFar = unumTooFar;
        if (playerType != null) {
            // version 18+: each player type has its own fading lengths
            unumFar = number(playerType, "unum_far_length", unumFar);
            unumTooFar = number(playerType, "unum_too_far_length", unumTooFar);
            teamFar = number(playerType, "team_far_length", teamFar);
            teamTooFar = number(playerType, "team_too_far_length", teamTooFar);
            ballFar = number(playerType, "ball_vel_far_length", ballFar);
            ballTooFar = number(playerType, "ball_vel_too_far_length", ballTooFar);
            flagFar = number(playerType, "flag_chg_far_length", flagFar);
            flagTooFar = number(playerType, "flag_chg_too_far_length", flagTooFar);
        }
        return new VisionParams(number(serverParam, "visible_distance", d.visibleDistance),
                number(serverParam, "quantize_step", d.quantizeStep),
                number(serverParam, "quantize_step_l", d.quantizeStepL), unumFar, unumTooFar, teamFar, teamTooFar,
                ballFar, ballTooFar, flagFar, flagTooFar);
    }

    private static double number(Map<String, String> named, String name, double fallback) {
        return Parameters.number(named, name, fallback);
    }
}
