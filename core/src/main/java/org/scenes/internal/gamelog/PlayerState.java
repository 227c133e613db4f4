package org.scenes.internal.gamelog;

import org.scenes.api.Side;

/**
 * One player's state in a {@link GameFrame}, the fields of its slot in a game log's {@code show}.
 *
 * @param type the heterogeneous player type (0 = default)
 * @param state the server's state flags ({@code 0x1} standing, {@code 0x8} goalie, ...)
 * @param body body direction in degrees, world frame (0 = towards x+, positive clockwise on screen)
 * @param neck neck angle relative to the body, degrees
 * @param viewQuality {@code 'h'} high or {@code 'l'} low
 * @param viewWidth the view cone's width in degrees (60 narrow, 90 or 120 normal, 180 wide)
 */
public record PlayerState(Side side, int unum, int type, int state, double x, double y, double vx, double vy,
                          double body, double neck, char viewQuality, double viewWidth, double stamina,
                          double effort, double recovery, double capacity, Counts counts) {
    /** State flag of a player in the game. */
    public static final int STANDING = 0x1;
    /** State flag of the goalie. */
    public static final int GOALIE = 0x8;

    /** Commands executed so far, in the order a game log's {@code (c ...)} lists them. */
    public record Counts(int kick, int dash, int turn, int catches, int move, int turnNeck, int changeView,
                         int say, int tackle, int pointto, int attentionto) {
    }
}
