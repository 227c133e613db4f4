package org.scenes.agent.sim;

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

    static final ServerParams DEFAULT = new ServerParams(2.7, 0.94, 0.05, 0.085, 3, 0.006, 0.005, 0.3, 0.01, 0.6,
            0.6, 14.02, 5, 0.027, 0.1, 0.7, 180, -180, 90, -90, 100, -100, 1, 0.4, 0.1, 0.3, 1.05, 0.1, 0.01,
            0.002, 0.3, 0.5, 45, 8000, 90, 3, 150, 100, 100);

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
}
