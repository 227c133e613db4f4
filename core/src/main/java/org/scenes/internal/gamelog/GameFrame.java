package org.scenes.internal.gamelog;

import java.util.List;

/**
 * The state of a game after one simulator step, as a game log's {@code show} records it.
 *
 * @param time the game clock (it stands still before kick-off and after goals)
 * @param playMode the referee's word for the play mode: {@code before_kick_off}, {@code play_on},
 *                 {@code kick_off_l}, {@code goal_r_2} ...
 * @param leftTeam left team's name, empty when no left team connected
 * @param rightTeam right team's name, empty when none
 * @param players every player in the game, left team first, by uniform number (disabled slots of
 *                a game log, state 0, are not players)
 */
public record GameFrame(int time, String playMode, String leftTeam, String rightTeam, int scoreLeft,
                        int scoreRight, BallState ball, List<PlayerState> players) {
    public GameFrame {
        players = List.copyOf(players);
    }

    /** Ball position and velocity in server coordinates (x right, y down, metres). */
    public record BallState(double x, double y, double vx, double vy) {
    }
}
