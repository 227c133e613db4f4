package org.scenes.agent.sim;

/** The play modes this simulator uses; {@code announced} is the referee's word without the side. */
enum PlayMode {
    BEFORE_KICK_OFF(false),
    KICK_OFF(true),
    PLAY_ON(true),
    /** After a goal, until the next kick-off: the clock stands still. */
    AFTER_GOAL(false),
    /** Between the halves: the clock stands still. */
    HALF_TIME(false),
    TIME_OVER(false);

    final boolean clockRuns;

    PlayMode(boolean clockRuns) {
        this.clockRuns = clockRuns;
    }

    /** Whether players may {@code move} (teleport) in this mode. */
    boolean allowsMove() {
        return this == BEFORE_KICK_OFF || this == AFTER_GOAL || this == HALF_TIME;
    }
}
