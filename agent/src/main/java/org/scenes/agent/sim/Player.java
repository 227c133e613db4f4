package org.scenes.agent.sim;

import org.scenes.scene.Side;

/** One player's body as the server keeps it, with its command counters. */
final class Player extends MovingObject {
    final String team;
    final Side side;
    final int unum;
    /** Body direction in degrees, world frame (0 = towards x+, positive = clockwise on screen). */
    double body;
    /** Neck angle relative to the body. */
    double neck;
    double stamina;
    double effort = 1;
    double recovery = 1;
    int kicks;
    int dashes;
    int turns;
    int turnNecks;
    int moves;
    /** Whether a world-changing command was already executed this cycle. */
    boolean acted;

    Player(String team, Side side, int unum, double stamina) {
        this.team = team;
        this.side = side;
        this.unum = unum;
        this.stamina = stamina;
        this.body = side == Side.LEFT ? 0 : 180;
    }

    double head() {
        return Numbers.normalize(body + neck);
    }
}
