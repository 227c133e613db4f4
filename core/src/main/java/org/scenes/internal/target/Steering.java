package org.scenes.internal.target;

import org.scenes.api.Action;
import org.scenes.api.ActionType;

/**
 * What one player's previous decisions chose, so the next does not undo them. Once it runs for
 * the ball it keeps at it while at least {@link #KEEP} of its neighbours ran to the ball, so a share
 * that wavers around a half does not turn it from the ball to its spot and back every cycle; and
 * a turn that would reverse its previous turn gives way to a neighbour's target that does not (the
 * body direction is part of what neighbours are matched by, so facing one way can select scenes
 * that turn back, and facing back scenes that turn again). A run to a spot follows a moving
 * average of the neighbours' destinations ({@link #NEW_DESTINATION}). Not thread-safe: one per player.
 */
public final class Steering {
    /** The share of ball runs among the neighbours that starts a chase. */
    static final double START = 0.5;
    /** The share that keeps a chase going. */
    static final double KEEP = 1 / 3.0;
    /** A turn back by less than this follows a correction, not a search (whose turns are large). */
    static final double REVERSAL = 90;

    /**
     * The weight of a new destination against the previous one: the neighbours change from step to
     * step as the view does, and their mean destination jumps by metres, so a player following each
     * one turns back and forth; a moving average over about three decisions keeps the run's line.
     */
    static final double NEW_DESTINATION = 0.35;

    private boolean chasing;
    /** the destination of the previous decision that ran to a spot, or null */
    private double[] destination;
    /** the moment of the latest body command when it was a turn, else 0 */
    private double lastTurn;

    /** Whether this share of ball runs sends the player for the ball now; remembered for the next decision. */
    boolean chase(double ballRunShare) {
        chasing = chasing ? ballRunShare >= KEEP : ballRunShare > START;
        if (chasing) {
            destination = null;
        }
        return chasing;
    }

    /** The spot to run to now for the neighbours' {@code mean} destination, and remembered for the next. */
    double[] spot(double[] mean) {
        destination = destination == null ? mean.clone() : new double[] {
            destination[0] + NEW_DESTINATION * (mean[0] - destination[0]),
            destination[1] + NEW_DESTINATION * (mean[1] - destination[1])};
        return destination.clone();
    }

    /** Whether {@code body} turns back against the previous body command, itself a turn. */
    public boolean reverses(Action body) {
        return body.type() == ActionType.TURN && lastTurn != 0 && Math.signum(body.first()) == -Math.signum(lastTurn)
                && Math.abs(body.first()) < REVERSAL && Math.abs(lastTurn) < REVERSAL;
    }

    /** Remembers the body command sent. */
    public void sent(Action body) {
        lastTurn = body != null && body.type() == ActionType.TURN ? body.first() : 0;
    }
}
