package org.scenes.internal.world;

/**
 * rcssserver's default parameters for the default player type, the one home of the values the
 * world model, the targets and the simulator share (a server that sends other values in its
 * {@code server_param} is not followed by the world model: see docs/conversion.md).
 */
public final class ServerDefaults {
    public static final double PLAYER_DECAY = 0.4;
    public static final double BALL_DECAY = 0.94;
    public static final double INERTIA_MOMENT = 5;
    public static final double KICK_POWER_RATE = 0.027;
    public static final double KICKABLE_MARGIN = 0.7;
    public static final double PLAYER_SIZE = 0.3;
    public static final double BALL_SIZE = 0.085;
    /** How near the ball must be to the player's centre to be kicked. */
    public static final double KICKABLE_AREA = KICKABLE_MARGIN + PLAYER_SIZE + BALL_SIZE;
    public static final double BALL_ACCEL_MAX = 2.7;
    /** The tackle area: in front of the body up to this far (behind it, none since rcssserver 12)... */
    public static final double TACKLE_DIST = 2;
    /** ...and this far to either side; the failure probability grows with this power of both ratios. */
    public static final double TACKLE_WIDTH = 1.25;
    public static final double TACKLE_EXPONENT = 6;
    public static final double MAX_POWER = 100;
    public static final double MAX_MOMENT = 180;
    public static final double MAX_NECK_ANGLE = 90;
    public static final double STAMINA_MAX = 8000;
    /** Below this share of {@link #STAMINA_MAX} the server lowers the player's effort, for good. */
    public static final double EFFORT_DEC_THR = 0.3;
    /** A ball or player this near is in every see, whichever way the player faces. */
    public static final double VISIBLE_DISTANCE = 3;
    /** Half the narrowest view cone (narrow view, asynchronous vision: 45 degrees in all). */
    public static final double NARROWEST_HALF_VIEW = 22.5;

    private ServerDefaults() {
    }
}
