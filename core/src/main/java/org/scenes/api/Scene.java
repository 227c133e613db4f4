package org.scenes.api;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import java.util.stream.Collectors;

/**
 * What one player saw in one cycle and what it did in response: the latest {@code see}
 * of the cycle and the command(s) sent after it. At most two actions; the first is the
 * primary one, the world-changing command when there is one.
 *
 * @param cycle the server cycle of the {@code see} (the cycle the actions were sent in, for a
 *              player that acts every cycle; see {@code seeAge})
 * @param observer the player who saw
 * @param objects the seen objects, in server order
 * @param actions at most two actions, primary first
 * @param previous the same player's scene before this one, carried by the {@code memory}
 *                 transform so metrics can weigh it (with the scenes it remembers in turn, up to
 *                 {@link #MAX_MEMORY} in all); null when not remembered. Never written to
 *                 scene files: it is rebuilt from the order of the scenes when they are read.
 * @param seeAge cycles between the {@code see} the objects come from and {@code cycle}: 0 when the
 *               player saw in the cycle it acted, 1 when it acted on the see of the cycle before
 *               (synchronous vision sends a see every other cycle in normal view)
 * @param world what the player believed about the game in {@code cycle} (its world model), or null
 *              when the scene was made without one
 */
public record Scene(int cycle, Observer observer, List<SeenObject> objects, List<Action> actions, Scene previous,
                    int seeAge, World world) {
    /** The most actions a scene holds: the primary one and one more (e.g. a turn_neck). */
    public static final int MAX_ACTIONS = 2;
    /** The longest chain of remembered scenes a scene may carry ({@link #withHistory}). */
    public static final int MAX_MEMORY = 8;

    /**
     * A scene without memory, made from the see of its own cycle.
     *
     * @param cycle the server cycle of the {@code see}
     * @param observer the player who saw (null for unknown)
     * @param objects the seen objects, in server order
     * @param actions at most {@link #MAX_ACTIONS} actions, primary first
     */
    public Scene(int cycle, Observer observer, List<SeenObject> objects, List<Action> actions) {
        this(cycle, observer, objects, actions, null, 0);
    }

    /**
     * A scene made from the see of its own cycle.
     *
     * @param cycle the server cycle of the {@code see}
     * @param observer the player who saw (null for unknown)
     * @param objects the seen objects, in server order
     * @param actions at most {@link #MAX_ACTIONS} actions, primary first
     * @param previous the same player's scene before this one, or null
     */
    public Scene(int cycle, Observer observer, List<SeenObject> objects, List<Action> actions, Scene previous) {
        this(cycle, observer, objects, actions, previous, 0);
    }

    /**
     * A scene without world model.
     *
     * @param cycle the server cycle of the {@code see}
     * @param observer the player who saw (null for unknown)
     * @param objects the seen objects, in server order
     * @param actions at most {@link #MAX_ACTIONS} actions, primary first
     * @param previous the same player's scene before this one, or null
     * @param seeAge cycles between the {@code see} and {@code cycle}, 0 or more
     */
    public Scene(int cycle, Observer observer, List<SeenObject> objects, List<Action> actions, Scene previous,
                 int seeAge) {
        this(cycle, observer, objects, actions, previous, seeAge, null);
    }

    /**
     * Copies the lists, bounds the memory chain and checks the action count and see age.
     *
     * @param cycle the server cycle of the {@code see}
     * @param observer the player who saw (null for unknown)
     * @param objects the seen objects, in server order
     * @param actions at most {@link #MAX_ACTIONS} actions, primary first
     * @param previous the same player's scene before this one, or null
     * @param seeAge cycles between the {@code see} and {@code cycle}, 0 or more
     * @param world the player's world model in {@code cycle}, or null
     */
    public Scene {
        observer = observer == null ? Observer.UNKNOWN : observer;
        objects = List.copyOf(objects);
        actions = List.copyOf(actions);
        if (seeAge < 0) {
            throw new IllegalArgumentException("a scene's see age is 0 or more, not " + seeAge);
        }
        if (actions.size() > MAX_ACTIONS) {
            throw new IllegalArgumentException("a scene holds at most " + MAX_ACTIONS + " actions, not " + actions.size());
        }
        // a bounded chain: one through every earlier scene would keep a whole game alive
        if (previous != null && previous.memoryDepth() >= MAX_MEMORY) {
            previous = previous.truncated(MAX_MEMORY - 1);
        }
    }

    /**
     * The same scene remembering {@code earlier} (its own memory dropped), or forgetting when null.
     *
     * @param earlier the scene to remember, or null
     * @return the scene with one remembered scene at most
     */
    public Scene withPrevious(Scene earlier) {
        return new Scene(cycle, observer, objects, actions, earlier == null ? null : earlier.withPrevious(null), seeAge,
                world);
    }

    /**
     * The same scene remembering {@code earlier} with the chain {@code earlier} remembers, cut
     * after {@link #MAX_MEMORY} scenes in all: what a transform keeping several steps builds.
     *
     * @param earlier the scene to remember, with its own memory
     * @return the scene with the chain
     */
    public Scene withHistory(Scene earlier) {
        return new Scene(cycle, observer, objects, actions, earlier, seeAge, world);
    }

    /**
     * How many remembered scenes this one carries: 0 without memory.
     *
     * @return the length of the chain of {@link #previous} scenes
     */
    public int memoryDepth() {
        int depth = 0;
        for (Scene s = previous; s != null; s = s.previous) {
            depth++;
        }
        return depth;
    }

    private Scene truncated(int depth) {
        return depth == 0 ? withPrevious(null)
                : new Scene(cycle, observer, objects, actions, previous == null ? null : previous.truncated(depth - 1), seeAge,
                        world);
    }

    /**
     * The primary action, or null for a scene without action.
     *
     * @return the first action or null
     */
    public Action primaryAction() {
        return actions.isEmpty() ? null : actions.get(0);
    }

    /**
     * The primary action's type, {@link ActionType#NONE} when there is none.
     *
     * @return the type of the first action
     */
    public ActionType actionType() {
        return actions.isEmpty() ? ActionType.NONE : actions.get(0).type();
    }

    /**
     * The same scene (cycle, observer, actions, memory, see age) holding other objects.
     *
     * @param newObjects the objects it holds instead
     * @return the copy
     */
    public Scene withObjects(List<SeenObject> newObjects) {
        return new Scene(cycle, observer, newObjects, actions, previous, seeAge, world);
    }

    /*
     * Set operations on the objects of two scenes, objects being the same when their
     * SeenObject.identity() is (kind, name, relation, team, uniform number). Each result is this
     * scene (cycle, observer, actions, memory) with the resulting objects: this scene's own
     * objects keep their order and values, the other's follow in theirs.
     */

    /**
     * This scene's objects, then those of {@code other} whose identity none of this scene's has.
     *
     * @param other the scene whose objects are added
     * @return this scene with the union of the objects
     */
    public Scene union(Scene other) {
        Set<String> own = identities(this);
        List<SeenObject> joined = new ArrayList<>(objects);
        Set<String> added = new HashSet<>();
        for (SeenObject object : other.objects) {
            if (!own.contains(object.identity()) && added.add(object.identity())) {
                joined.add(object);
            }
        }
        return withObjects(joined);
    }

    /**
     * This scene's objects whose identity {@code other} holds too.
     *
     * @param other the scene whose objects are kept
     * @return this scene with the common objects
     */
    public Scene intersection(Scene other) {
        Set<String> theirs = identities(other);
        return keep(object -> theirs.contains(object.identity()));
    }

    /**
     * This scene's objects whose identity {@code other} does not hold.
     *
     * @param other the scene whose objects are dropped
     * @return this scene with the objects only it holds
     */
    public Scene difference(Scene other) {
        Set<String> theirs = identities(other);
        return keep(object -> !theirs.contains(object.identity()));
    }

    private Scene keep(Predicate<SeenObject> wanted) {
        return withObjects(objects.stream().filter(wanted).toList());
    }

    private static Set<String> identities(Scene scene) {
        return scene.objects.stream().map(SeenObject::identity).collect(Collectors.toSet());
    }

    /**
     * The same scene with objects re-assigned to the cells of another grid.
     *
     * @param grid the grid giving the new cells
     * @return the copy, its remembered scenes re-gridded too
     */
    public Scene regrid(Grid grid) {
        return new Scene(cycle, observer,
                objects.stream().map(o -> o.withCell(grid.cell(o.distance(), o.direction()))).toList(), actions,
                previous == null ? null : previous.regrid(grid), seeAge, world);
    }

    /**
     * The same scene with another world model.
     *
     * @param newWorld the world model it holds instead, or null for none
     * @return the copy
     */
    public Scene withWorld(World newWorld) {
        return new Scene(cycle, observer, objects, actions, previous, seeAge, newWorld);
    }
}
