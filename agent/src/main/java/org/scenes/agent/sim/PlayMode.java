package org.scenes.agent.sim;

/** The play modes this simulator uses; a restart's referee word is {@code word + "_" + side}. */
enum PlayMode {
    BEFORE_KICK_OFF(false, "before_kick_off"),
    KICK_OFF(true, "kick_off"),
    KICK_IN(true, "kick_in"),
    CORNER_KICK(true, "corner_kick"),
    GOAL_KICK(true, "goal_kick"),
    /** After a goalie caught the ball: the goalie's side kicks. */
    FREE_KICK(true, "free_kick"),
    PLAY_ON(true, "play_on"),
    /** After a goal, until the next kick-off: the clock stands still. */
    AFTER_GOAL(false, "goal"),
    /** Between the halves: the clock stands still. */
    HALF_TIME(false, "half_time"),
    TIME_OVER(false, "time_over");

    final boolean clockRuns;
    final String word;

    PlayMode(boolean clockRuns, String word) {
        this.clockRuns = clockRuns;
        this.word = word;
    }

    /** A restart: only the side awarded it may kick, the other keeps its distance. */
    boolean restart() {
        return this == KICK_OFF || this == KICK_IN || this == CORNER_KICK || this == GOAL_KICK || this == FREE_KICK;
    }

    /** Whether players may {@code move} (teleport) in this mode. */
    boolean allowsMove() {
        return this == BEFORE_KICK_OFF || this == AFTER_GOAL || this == HALF_TIME;
    }
}
