package org.scenes.simulator;

/** The play modes this simulator uses; a restart's referee word is {@code word + "_" + side}. */
enum PlayMode {
    /** Before the first kick-off and between the halves: players may move and turn, nothing else moves. */
    BEFORE_KICK_OFF(false, false, "before_kick_off"),
    KICK_OFF(true, true, "kick_off"),
    KICK_IN(true, true, "kick_in"),
    CORNER_KICK(true, true, "corner_kick"),
    GOAL_KICK(true, true, "goal_kick"),
    /** After a goalie caught the ball: the goalie's side kicks. */
    FREE_KICK(true, true, "free_kick"),
    PLAY_ON(true, true, "play_on"),
    /** After a goal, until the next kick-off: the clock stands still but players and ball move. */
    AFTER_GOAL(false, true, "goal"),
    TIME_OVER(false, false, "time_over");

    /** Whether the game clock advances. */
    final boolean clockRuns;
    /** Whether dashes, kicks and velocities move players and ball (the server's step). */
    final boolean objectsMove;
    final String word;

    PlayMode(boolean clockRuns, boolean objectsMove, String word) {
        this.clockRuns = clockRuns;
        this.objectsMove = objectsMove;
        this.word = word;
    }

    /** A restart: only the side awarded it may kick, the other keeps its distance. */
    boolean restart() {
        return this == KICK_OFF || this == KICK_IN || this == CORNER_KICK || this == GOAL_KICK || this == FREE_KICK;
    }

    /** Whether players may {@code move} (teleport) in this mode. */
    boolean allowsMove() {
        return this == BEFORE_KICK_OFF || this == AFTER_GOAL;
    }
}
