package org.scenes.scene;

import java.util.List;

/**
 * What one player saw in one cycle and what it did in response: the latest {@code see}
 * of the cycle and the command(s) sent after it. At most two actions; the first is the
 * primary one, the world-changing command when there is one.
 *
 * @param cycle the server cycle of the {@code see}
 * @param observer the player who saw
 * @param objects the seen objects, in server order
 * @param actions at most two actions, primary first
 * @param previous the same player's scene before this one, carried by the {@code memory}
 *                 transform so metrics can weigh it; null when not remembered. Never written to
 *                 scene files: it is rebuilt from the order of the scenes when they are read.
 */
public record Scene(int cycle, Observer observer, List<SeenObject> objects, List<Action> actions, Scene previous) {
    public static final int MAX_ACTIONS = 2;

    /** A scene without memory. */
    public Scene(int cycle, Observer observer, List<SeenObject> objects, List<Action> actions) {
        this(cycle, observer, objects, actions, null);
    }

    public Scene {
        observer = observer == null ? Observer.UNKNOWN : observer;
        objects = List.copyOf(objects);
        actions = List.copyOf(actions);
        if (actions.size() > MAX_ACTIONS) {
            throw new IllegalArgumentException("a scene holds at most " + MAX_ACTIONS + " actions, not " + actions.size());
        }
        // one step of memory only: a chain through every earlier scene would keep a whole game alive
        if (previous != null && previous.previous != null) {
            previous = previous.withPrevious(null);
        }
    }

    /** The same scene remembering {@code earlier} (its own memory dropped), or forgetting when null. */
    public Scene withPrevious(Scene earlier) {
        return new Scene(cycle, observer, objects, actions, earlier == null ? null : earlier.withPrevious(null));
    }

    /** The primary action, or null for a scene without action. */
    public Action primaryAction() {
        return actions.isEmpty() ? null : actions.get(0);
    }

    /** The primary action's type, {@link ActionType#NONE} when there is none. */
    public ActionType actionType() {
        return actions.isEmpty() ? ActionType.NONE : actions.get(0).type();
    }

    /** The same scene with objects re-assigned to the cells of another grid. */
    public Scene regrid(Grid grid) {
        return new Scene(cycle, observer,
                objects.stream().map(o -> o.withCell(grid.cell(o.distance(), o.direction()))).toList(), actions,
                previous == null ? null : previous.regrid(grid));
    }
}
