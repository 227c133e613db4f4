package org.scenes.simulator;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.scenes.internal.world.ServerDefaults.BALL_ACCEL_MAX;
import static org.scenes.internal.world.ServerDefaults.BALL_DECAY;
import static org.scenes.internal.world.ServerDefaults.BALL_SIZE;
import static org.scenes.internal.world.ServerDefaults.INERTIA_MOMENT;
import static org.scenes.internal.world.ServerDefaults.KICKABLE_MARGIN;
import static org.scenes.internal.world.ServerDefaults.KICK_POWER_RATE;
import static org.scenes.internal.world.ServerDefaults.MAX_MOMENT;
import static org.scenes.internal.world.ServerDefaults.MAX_NECK_ANGLE;
import static org.scenes.internal.world.ServerDefaults.MAX_POWER;
import static org.scenes.internal.world.ServerDefaults.PLAYER_DECAY;
import static org.scenes.internal.world.ServerDefaults.PLAYER_SIZE;

/**
 * The server parameters the simulator uses, with the values of the recorded version 9 games
 * (docs/simulator.md lists them). One instance, {@link #DEFAULT}; the text sent to clients is
 * {@link #serverParamMessage()}.
 */
record ServerParams(double ballAccelMax, double ballDecay, double ballRand, double ballSize, double ballSpeedMax,
                    double dashPowerRate, double effortDec, double effortDecThr, double effortInc,
                    double effortIncThr, double effortMin, double goalWidth, double inertiaMoment,
                    double kickPowerRate, double kickRand, double kickableMargin, double maxMoment,
                    double minMoment, double maxNeckAng, double minNeckAng, double maxPower, double minPower,
                    double playerAccelMax, double playerDecay, double playerRand, double playerSize,
                    double playerSpeedMax, double quantizeStep, double quantizeStepL, double recoverDec,
                    double recoverDecThr, double recoverMin, double staminaIncMax, double staminaMax,
                    double visibleAngle, double visibleDistance, int sendStep, int simulatorStep,
                    int senseBodyStep) {

    static final ServerParams DEFAULT = new ServerParams(BALL_ACCEL_MAX, BALL_DECAY, 0.05, BALL_SIZE, 3, 0.006,
            0.005, 0.3, 0.01, 0.6, 0.6, 14.02, INERTIA_MOMENT, KICK_POWER_RATE, 0.1, KICKABLE_MARGIN, MAX_MOMENT,
            -MAX_MOMENT, MAX_NECK_ANGLE, -MAX_NECK_ANGLE, MAX_POWER, -MAX_POWER, 1, PLAYER_DECAY, 0.1, PLAYER_SIZE,
            1.05, 0.1, 0.01, 0.002, 0.3, 0.5, 45, 8000, 90, 3, 150, 100, 100);

    /** Distances at which a seen player's uniform number and team fade (server defaults). */
    static final double UNUM_FAR_LENGTH = 20;
    static final double UNUM_TOO_FAR_LENGTH = 40;
    static final double TEAM_FAR_LENGTH = 40;
    static final double TEAM_TOO_FAR_LENGTH = 60;

    /** Pitch half sizes and how far outside the pitch a player may go. */
    static final double PITCH_HALF_LENGTH = 52.5;
    static final double PITCH_HALF_WIDTH = 34;
    static final double PITCH_MARGIN = 5;

    double kickableDistance() {
        return playerSize + ballSize + kickableMargin;
    }

    /** The abbreviated v8+ {@code server_param} message: the parameters this simulator uses. */
    String serverParamMessage() {
        return "(server_param " + pair("ball_accel_max", ballAccelMax) + pair("ball_decay", ballDecay)
                + pair("ball_rand", ballRand) + pair("ball_size", ballSize) + pair("ball_speed_max", ballSpeedMax)
                + pair("dash_power_rate", dashPowerRate) + pair("effort_dec", effortDec)
                + pair("effort_dec_thr", effortDecThr) + pair("effort_inc", effortInc)
                + pair("effort_inc_thr", effortIncThr) + pair("effort_min", effortMin)
                + pair("goal_width", goalWidth) + pair("inertia_moment", inertiaMoment)
                + pair("kick_power_rate", kickPowerRate) + pair("kick_rand", kickRand)
                + pair("kickable_margin", kickableMargin) + pair("maxmoment", maxMoment)
                + pair("maxneckang", maxNeckAng) + pair("maxpower", maxPower) + pair("minmoment", minMoment)
                + pair("minneckang", minNeckAng) + pair("minpower", minPower)
                + pair("player_accel_max", playerAccelMax) + pair("player_decay", playerDecay)
                + pair("player_rand", playerRand) + pair("player_size", playerSize)
                + pair("player_speed_max", playerSpeedMax) + pair("quantize_step", quantizeStep)
                + pair("quantize_step_l", quantizeStepL) + pair("recover_dec", recoverDec)
                + pair("recover_dec_thr", recoverDecThr) + pair("recover_min", recoverMin)
                + pair("send_step", sendStep) + pair("sense_body_step", senseBodyStep)
                + pair("simulator_step", simulatorStep) + pair("stamina_inc_max", staminaIncMax)
                + pair("stamina_max", staminaMax) + pair("visible_angle", visibleAngle)
                + pair("visible_distance", visibleDistance) + ")";
    }

    /** Only the default player type exists: heterogeneous players are not modelled. */
    String playerParamMessage() {
        return "(player_param (player_types 1)(pt_max 1)(subs_max 0))";
    }

    String playerTypeMessage() {
        return "(player_type (id 0)" + pair("player_speed_max", playerSpeedMax)
                + pair("stamina_inc_max", staminaIncMax) + pair("player_decay", playerDecay)
                + pair("inertia_moment", inertiaMoment) + pair("dash_power_rate", dashPowerRate)
                + pair("player_size", playerSize) + pair("kickable_margin", kickableMargin)
                + pair("kick_rand", kickRand) + "(extra_stamina 0)(effort_max 1)" + pair("effort_min", effortMin)
                + ")";
    }

    private static String pair(String name, double value) {
        return "(" + name + " " + Numbers.format(value, 6) + ")";
    }

    /**
     * The version 7 {@code server_param}: values only, in the server's fixed order. The modelled
     * parameters take this simulator's values; the others the server's defaults, but coach
     * modes off.
     */
    String serverParamMessageV7(int halfTime, int dropBallTime) {
        Map<String, String> ours = new HashMap<>();
        ours.put("goalWidth", n(goalWidth));
        ours.put("inertiaMoment", n(inertiaMoment));
        ours.put("playerSize", n(playerSize));
        ours.put("playerDecay", n(playerDecay));
        ours.put("playerRand", n(playerRand));
        ours.put("playerSpeedMax", n(playerSpeedMax));
        ours.put("playerAccelMax", n(playerAccelMax));
        ours.put("staminaMax", n(staminaMax));
        ours.put("staminaInc", n(staminaIncMax));
        ours.put("recoverDecThr", n(recoverDecThr));
        ours.put("recoverMin", n(recoverMin));
        ours.put("recoverDec", n(recoverDec));
        ours.put("effortDecThr", n(effortDecThr));
        ours.put("effortMin", n(effortMin));
        ours.put("effortDec", n(effortDec));
        ours.put("effortIncThr", n(effortIncThr));
        ours.put("effortInc", n(effortInc));
        ours.put("kickRand", n(kickRand));
        ours.put("ballSize", n(ballSize));
        ours.put("ballDecay", n(ballDecay));
        ours.put("ballRand", n(ballRand));
        ours.put("ballSpeedMax", n(ballSpeedMax));
        ours.put("ballAccelMax", n(ballAccelMax));
        ours.put("dashPowerRate", n(dashPowerRate));
        ours.put("kickPowerRate", n(kickPowerRate));
        ours.put("kickableMargin", n(kickableMargin));
        ours.put("maxPower", n(maxPower));
        ours.put("minPower", n(minPower));
        ours.put("maxMoment", n(maxMoment));
        ours.put("minMoment", n(minMoment));
        ours.put("maxNeckAngle", n(maxNeckAng));
        ours.put("minNeckAngle", n(minNeckAng));
        ours.put("visibleAngleDegree", n(visibleAngle));
        ours.put("visibleDistance", n(visibleDistance));
        ours.put("kickableArea", n(kickableDistance()));
        ours.put("catchAreaLength", n(CATCHABLE_AREA_L));
        ours.put("catchAreaWidth", n(CATCHABLE_AREA_W));
        ours.put("catchBanCycle", Integer.toString(CATCH_BAN_CYCLE));
        ours.put("halfTime", Integer.toString(halfTime));
        ours.put("simStep", Integer.toString(simulatorStep));
        ours.put("sendStep", Integer.toString(sendStep));
        ours.put("senseBodyStep", Integer.toString(senseBodyStep));
        ours.put("quantizeStep", n(quantizeStep));
        ours.put("landmarkQuantizeStep", n(quantizeStepL));
        ours.put("coachMode", "0");
        ours.put("coachWithRefereeMode", "0");
        ours.put("dropTime", Integer.toString(dropBallTime));
        StringBuilder text = new StringBuilder("(server_param");
        for (String entry : V7_ORDER) {
            int space = entry.indexOf(' ');
            String name = entry.substring(0, space);
            text.append(' ').append(ours.getOrDefault(name, entry.substring(space + 1)));
        }
        return text.append(')').toString();
    }

    /** The version 7 {@code player_param}: one player type, no substitutions. */
    String playerParamMessageV7() {
        return "(player_param 1 0 1 0 0 0 -0.1 0.1 25 0 0 -100 -0.1 0.1 1 0 50 -0.004 -0.004)";
    }

    /** The version 7 {@code player_type}: the default type's values in the server's order. */
    String playerTypeMessageV7() {
        return "(player_type 0 " + n(playerSpeedMax) + ' ' + n(staminaIncMax) + ' ' + n(playerDecay) + ' '
                + n(inertiaMoment) + ' ' + n(dashPowerRate) + ' ' + n(playerSize) + ' ' + n(kickableMargin) + ' '
                + n(kickRand) + " 0 1 " + n(effortMin) + ")";
    }

    private static String n(double value) {
        return Numbers.format(value, 6);
    }

    /** Goalie catches: the catchable area's length and width, and the cycles between attempts. */
    static final double CATCHABLE_AREA_L = 1.2;
    static final double CATCHABLE_AREA_W = 1;
    static final int CATCH_BAN_CYCLE = 5;

    /** The version 7 server_param's order (the server's accessor names) with the server's defaults. */
    private static final List<String> V7_ORDER = List.of(
            "goalWidth 14.02", "inertiaMoment 5", "playerSize 0.3", "playerDecay 0.4", "playerRand 0.1",
            "playerWeight 60", "playerSpeedMax 1.05", "playerAccelMax 1", "staminaMax 8000", "staminaInc 45",
            "recoverInit 1", "recoverDecThr 0.3", "recoverMin 0.5", "recoverDec 0.002", "effortInit 1",
            "effortDecThr 0.3", "effortMin 0.6", "effortDec 0.005", "effortIncThr 0.6", "effortInc 0.01",
            "kickRand 0.1", "teamActuatorNoise 0", "playerRandFactorLeft 1", "playerRandFactorRight 1", "kickRandFactorLeft 1",
            "kickRandFactorRight 1", "ballSize 0.085", "ballDecay 0.94", "ballRand 0.05", "ballWeight 0.2",
            "ballSpeedMax 3", "ballAccelMax 2.7", "dashPowerRate 0.006", "kickPowerRate 0.027", "kickableMargin 0.7",
            "controlRadius 2", "controlRadiusWidth 1.7", "maxPower 100", "minPower -100", "maxMoment 180",
            "minMoment -180", "maxNeckMoment 180", "minNeckMoment -180", "maxNeckAngle 90", "minNeckAngle -90",
            "visibleAngleDegree 90", "visibleDistance 3", "windDir 0", "windForce 0", "windAngle 0",
            "windRand 0", "kickableArea 1.085", "catchAreaLength 1.2", "catchAreaWidth 1", "catchProbability 1",
            "goalieMaxMoves 2", "cornerKickMargin 1", "offsideActiveArea 2.5", "windNone 0", "windRandom 0",
            "freeformCountMax 128", "freeformMsgSize 128", "clangWinSize 300", "clangDefineWin 1", "clangMetaWin 1",
            "clangAdviceWin 1", "clangInfoWin 1", "clangMessDelay 50", "clangMessPerCycle 1", "halfTime 3000",
            "simStep 100", "sendStep 150", "recvStep 10", "senseBodyStep 100", "lcmStep 300",
            "sayMsgSize 10", "hearMax 1", "hearInc 1", "hearDecay 1", "catchBanCycle 5",
            "slowDownFactor 1", "useOffside 1", "kickOffOffside 1", "offsideKickMargin 9.15", "audioCutDist 50",
            "quantizeStep 0.1", "landmarkQuantizeStep 0.01", "dirQStep -1", "distQStepLeft -1", "distQStepRight -1",
            "landQStepLeft -1", "landQStepRight -1", "dirQStepLeft -1", "dirQStepRight -1", "coachMode 1",
            "coachWithRefereeMode 1", "coachOldHear 0", "coachVisualStep 100", "startGoalLeft 0", "startGoalRight 0",
            "fullstateLeft 0", "fullstateRight 0", "dropTime 100");
}
