package org.scenes.api;

import java.util.List;

/**
 * The classes a scene's actions are scored by. {@link #PRIMARY} is the classic figure, the type of
 * the primary action. For players that act every cycle the body and the neck are scored apart and
 * together, and a command that changes nothing ({@code (turn 0)}, librcsc's "do nothing",
 * {@code (dash 0)}, {@code (kick 0 ...)}, {@code (turn_neck 0)}) is a class of its own,
 * {@value #NO_OP}, rather than a turn, dash or kick.
 */
public enum ActionLabel {
    /** The primary action's type ({@code none} without action): the figure of the thesis. */
    PRIMARY("accuracy"),
    /** The world-changing command (dash, turn, kick, catch, move, tackle, noop or none). */
    BODY("bodyAccuracy"),
    /** The neck: turn_neck, noop ({@code (turn_neck 0)}) or none. */
    NECK("neckAccuracy"),
    /** Body and neck both right. */
    BOTH("bothAccuracy");

    /** The class of a scene without the action looked at. */
    public static final String NONE = "none";
    /** The class of a command that changes nothing, e.g. {@code (turn 0)}. */
    public static final String NO_OP = "noop";

    private final String figure;

    ActionLabel(String figure) {
        this.figure = figure;
    }

    /**
     * The name of this label's accuracy in reports and JSON: {@code accuracy}, {@code bodyAccuracy}, ...
     *
     * @return the figure's name
     */
    public String figure() {
        return figure;
    }

    /**
     * The class of a scene's (or a prediction's) actions, primary first.
     *
     * @param actions the actions, primary first
     * @return a type key, {@value #NONE}, {@value #NO_OP}, or body and neck joined by {@code +}
     */
    public String of(List<Action> actions) {
        return switch (this) {
            case PRIMARY -> actions.isEmpty() ? NONE : actions.get(0).type().key();
            case BODY -> body(actions);
            case NECK -> neck(actions);
            case BOTH -> body(actions) + "+" + neck(actions);
        };
    }

    /**
     * The first world-changing action, or null.
     *
     * @param actions the actions, primary first
     * @return the body command or null
     */
    public static Action bodyAction(List<Action> actions) {
        for (Action action : actions) {
            if (action.type().worldChanging()) {
                return action;
            }
        }
        return null;
    }

    /**
     * The first turn_neck, or null.
     *
     * @param actions the actions, primary first
     * @return the neck command or null
     */
    public static Action neckAction(List<Action> actions) {
        for (Action action : actions) {
            if (action.type() == ActionType.TURN_NECK) {
                return action;
            }
        }
        return null;
    }

    /**
     * Whether the server, executing this command, changes nothing: a turn, dash, kick or turn_neck of 0.
     *
     * @param action the command
     * @return true when its first parameter is 0 for one of those types
     */
    public static boolean changesNothing(Action action) {
        return switch (action.type()) {
            case TURN, DASH, KICK, TURN_NECK -> action.first() == 0;
            default -> false;
        };
    }

    private static String body(List<Action> actions) {
        Action body = bodyAction(actions);
        return body == null ? NONE : changesNothing(body) ? NO_OP : body.type().key();
    }

    private static String neck(List<Action> actions) {
        Action neck = neckAction(actions);
        return neck == null ? NONE : changesNothing(neck) ? NO_OP : neck.type().key();
    }
}
