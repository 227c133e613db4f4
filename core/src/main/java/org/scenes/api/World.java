package org.scenes.api;

import java.util.List;

/**
 * What the player believed about the game in a scene's cycle, built from its percepts alone (its
 * sees, {@code sense_body} and the referee's calls): where it stands and faces, its speed and
 * stamina, where the ball is going, the players it remembers, the play mode and the score.
 *
 * <p>Positions and directions are in the player's <em>own frame</em>: metres from the centre spot,
 * its team attacking towards +x, y towards the server's bottom touchline for the left team (the
 * right team's frame is the server's turned by 180 degrees, so both teams' scenes compare alike);
 * directions in degrees, 0 along +x, positive turning from +x towards +y, as the server counts them.
 * A value the percepts never gave is {@code NaN} (a player that has seen no flag yet has no
 * position). Ages count the cycles since the value was last seen; a value is carried on by motion
 * meanwhile.
 *
 * @param x own position along the pitch, metres
 * @param y own position across the pitch, metres
 * @param body body direction, degrees
 * @param neck head angle relative to the body, degrees (from {@code sense_body})
 * @param vx own velocity along x, metres per cycle
 * @param vy own velocity along y, metres per cycle
 * @param stamina stamina as {@code sense_body} reported it
 * @param effort effort as {@code sense_body} reported it
 * @param age cycles since the position was last estimated from a see, -1 when never
 * @param ballX the ball's position along x
 * @param ballY the ball's position across
 * @param ballVx the ball's velocity along x, metres per cycle
 * @param ballVy the ball's velocity across, metres per cycle
 * @param ballAge cycles since the ball was last seen (or placed by the referee at a kick-off), -1 when unknown
 * @param players the players seen in the latest see and those remembered from earlier ones
 * @param playMode the referee's latest play mode, as the server words it ({@code play_on},
 *                 {@code kick_off_l}, {@code goal_r} ...), empty when none was heard
 * @param ownScore goals of the player's team
 * @param opponentScore goals of the other team
 */
public record World(double x, double y, double body, double neck, double vx, double vy, double stamina,
                    double effort, int age, double ballX, double ballY, double ballVx, double ballVy, int ballAge,
                    List<Player> players, String playMode, int ownScore, int opponentScore) {

    /**
     * A player in the world model.
     *
     * @param relation teammate, opponent, or unknown when the team was not readable
     * @param unum uniform number, 0 when not readable
     * @param x position along x, own frame
     * @param y position across, own frame
     * @param age cycles since it was seen there
     */
    public record Player(Relation relation, int unum, double x, double y, int age) {
    }

    /**
     * Copies the list; a null play mode becomes empty.
     *
     * @param x own position along the pitch, metres
     * @param y own position across the pitch, metres
     * @param body body direction, degrees
     * @param neck head angle relative to the body, degrees
     * @param vx own velocity along x
     * @param vy own velocity along y
     * @param stamina stamina
     * @param effort effort
     * @param age cycles since the position was last estimated from a see
     * @param ballX the ball's position along x
     * @param ballY the ball's position across
     * @param ballVx the ball's velocity along x
     * @param ballVy the ball's velocity across
     * @param ballAge cycles since the ball was last seen (or placed at a kick-off), -1 when unknown
     * @param players the players seen and remembered
     * @param playMode the referee's latest play mode
     * @param ownScore goals of the player's team
     * @param opponentScore goals of the other team
     */
    public World {
        players = List.copyOf(players);
        playMode = playMode == null ? "" : playMode;
    }

    /**
     * Whether the player's position is known.
     *
     * @return false before its first see of a landmark
     */
    public boolean located() {
        return !Double.isNaN(x);
    }

    /**
     * Whether the ball's position is known.
     *
     * @return false before the ball was first seen
     */
    public boolean ballKnown() {
        return !Double.isNaN(ballX);
    }

    /**
     * The player's distance to the ball, as it believes both positions.
     *
     * @return NaN when its own or the ball's position is unknown
     */
    public double ballDistance() {
        return Math.hypot(ballX - x, ballY - y);
    }

    /**
     * Whether the player believes itself its team's nearest to the ball: it knows where it and the
     * ball are and no teammate it knows of stands nearer the ball.
     *
     * @return false when its own or the ball's position is unknown
     */
    public boolean nearestOfItsTeamToBall() {
        double own = ballDistance();
        if (Double.isNaN(own)) {
            return false;
        }
        for (Player player : players) {
            if (player.relation() == Relation.TEAMMATE && Math.hypot(ballX - player.x(), ballY - player.y()) < own) {
                return false;
            }
        }
        return true;
    }
}
