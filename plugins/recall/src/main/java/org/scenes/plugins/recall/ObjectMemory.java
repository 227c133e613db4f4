package org.scenes.plugins.recall;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.SeenObject;

/**
 * The memory of one player's sequence of scenes. Each object with an identity of its own (see
 * {@link SeenObject#identity()}; objects sensed behind and players without a readable number
 * have none and are never remembered) is kept with its last place, moved at every later scene:
 * <ol>
 * <li>by its own last reported changes, {@code distChange} and {@code dirChange} per cycle
 *     elapsed (objects seen without changes stay put);</li>
 * <li>by the player's own motion: the view's turn as the flags and goals seen in both scenes
 *     show it ({@link #observedTurn}); only without such landmarks from the commands of the
 *     scene before (a {@code turn} of moment m turns the body, and so the view, by m, a
 *     {@code turn_neck} the view by its angle, taken at rest: scenes carry no {@code sense_body});
 *     a {@code dash} of power p moves the player {@value #DASH_RATE} p metres ahead, without
 *     effort or stamina.</li>
 * </ol>
 * A remembered object that the move puts inside the view cone (the grid's angle range) or
 * within the {@value #FEEL_DISTANCE} m the server senses around the player, but that the scene
 * does not hold, is forgotten: had it been there, the server would have reported it. Objects are
 * forgotten after {@code horizon} cycles unseen; until then a remembered object's confidence is
 * {@code 1 - (age + 1) / (horizon + 2)} (age 0 when an object vanished within a cycle, as while play is paused).
 * The scene's own objects come first, the remembered ones after
 * them (so metrics that use the first ball listed use a seen one when there is one); a sequence
 * whose cycle goes back (a new game or file) starts with an empty memory.
 */
final class ObjectMemory implements SceneTransform {
    /** Metres a dash of power 1 moves the player in its first cycle (rcssserver's dash_power_rate). */
    static final double DASH_RATE = 0.006;
    /** The server's visible_distance: objects this near are sensed even outside the view cone. */
    static final double FEEL_DISTANCE = 3;

    private final int horizon;
    private final Grid grid = Grid.DEFAULT;
    private final Map<String, Remembered> memory = new LinkedHashMap<>();
    private Scene last;

    /** An object as last placed, and the cycle it was last seen. */
    private record Remembered(SeenObject object, double distance, double direction, int seenCycle) {
    }

    ObjectMemory(int horizon) {
        this.horizon = horizon;
    }

    @Override
    public Scene apply(Scene scene) {
        if (last != null && scene.cycle() < last.cycle()) {
            memory.clear();
            last = null;
        }
        checkGrid(scene);
        if (last != null) {
            move(scene.cycle() - last.cycle(), last.actions(), observedTurn(last, scene));
        }
        Set<String> seen = new HashSet<>();
        for (SeenObject object : scene.objects()) {
            String identity = identityOf(object);
            if (identity != null && !object.remembered()) {
                seen.add(identity);
                memory.put(identity, new Remembered(object, object.distance(), object.direction(), scene.cycle()));
            }
        }
        List<SeenObject> objects = new ArrayList<>(scene.objects());
        for (Iterator<Remembered> entries = memory.values().iterator(); entries.hasNext(); ) {
            Remembered entry = entries.next();
            if (seen.contains(identityOf(entry.object()))) {
                continue;
            }
            int age = scene.cycle() - entry.seenCycle();
            if (age > horizon || wouldBeSeen(entry)) {
                entries.remove();
                continue;
            }
            objects.add(entry.object().remembered(entry.distance(), entry.direction(),
                    1 - (age + 1) / (double) (horizon + 2), grid));
        }
        last = scene;
        return scene.withObjects(objects);
    }

    /** Remembers only objects that name one thing and whose place was reported. */
    private static String identityOf(SeenObject object) {
        boolean anonymous = object.behind() || (object.kind() == ObjectKind.PLAYER
                && object.uniformNumber() == 0);
        if (anonymous || Double.isNaN(object.distance()) || Double.isNaN(object.direction())) {
            return null;
        }
        return object.identity();
    }

    private boolean wouldBeSeen(Remembered entry) {
        return entry.distance() <= FEEL_DISTANCE
                || (entry.direction() >= grid.minAngle() && entry.direction() <= grid.maxAngle());
    }

    /**
     * How far the view turned between two scenes as the landmarks seen in both show it: the median
     * of their direction changes, reversed; NaN when they share none. A command sent after one see
     * takes effect by the next see only about half the time in the recorded games (the client sends
     * it at no fixed point of the cycle), so the landmarks say better than the command whether the
     * turn has happened yet.
     */
    static double observedTurn(Scene before, Scene after) {
        Map<String, Double> directions = new HashMap<>();
        for (SeenObject object : before.objects()) {
            if (landmark(object)) {
                directions.put(object.identity(), object.direction());
            }
        }
        List<Double> turns = new ArrayList<>();
        for (SeenObject object : after.objects()) {
            Double earlier = landmark(object) ? directions.get(object.identity()) : null;
            if (earlier != null) {
                turns.add(normalize(earlier - object.direction()));
            }
        }
        if (turns.isEmpty()) {
            return Double.NaN;
        }
        turns.sort(null);
        int middle = turns.size() / 2;
        return turns.size() % 2 == 1 ? turns.get(middle) : (turns.get(middle - 1) + turns.get(middle)) / 2;
    }

    /** Flags and goals stay put, so a change of their direction is the player's own turn (and a little parallax). */
    private static boolean landmark(SeenObject object) {
        return (object.kind() == ObjectKind.FLAG || object.kind() == ObjectKind.GOAL)
                && !object.remembered() && identityOf(object) != null;
    }

    /**
     * Moves every remembered object over {@code cycles} cycles, then by the player's own motion:
     * the view's turn as the landmarks show it ({@code observedTurn}), or without landmarks in both
     * scenes the turns commanded; the dash commanded.
     */
    private void move(int cycles, List<Action> commands, double observedTurn) {
        double turn = 0;
        double ahead = 0;
        for (Action command : commands) {
            if (command.type() == ActionType.TURN || command.type() == ActionType.TURN_NECK) {
                turn += finite(command.first());
            } else if (command.type() == ActionType.DASH && Double.isNaN(command.second())) {
                ahead += DASH_RATE * finite(command.first());
            }
        }
        if (!Double.isNaN(observedTurn)) {
            turn = observedTurn;
        }
        for (Map.Entry<String, Remembered> entry : memory.entrySet()) {
            Remembered old = entry.getValue();
            SeenObject object = old.object();
            double distance = old.distance() + cycles * finite(object.distanceChange());
            double direction = old.direction() + cycles * finite(object.directionChange());
            // the player moves `ahead` metres along its view, then turns the view by `turn`
            double radians = Math.toRadians(direction);
            double x = distance * Math.cos(radians) - ahead;
            double y = distance * Math.sin(radians);
            distance = Math.max(0, Math.hypot(x, y));
            direction = normalize(Math.toDegrees(Math.atan2(y, x)) - turn);
            entry.setValue(new Remembered(object, distance, direction, old.seenCycle()));
        }
    }

    private static double finite(double value) {
        return Double.isFinite(value) ? value : 0;
    }

    private static double normalize(double degrees) {
        double wrapped = degrees % 360;
        if (wrapped > 180) {
            wrapped -= 360;
        } else if (wrapped <= -180) {
            wrapped += 360;
        }
        return wrapped;
    }

    /** Remembered objects get cells of the default grid, so scenes of another grid are refused. */
    private void checkGrid(Scene scene) {
        for (SeenObject object : scene.objects()) {
            if (!Double.isNaN(object.distance()) && !Double.isNaN(object.direction()) && !object.remembered()
                    && !object.cell().equals(grid.cell(object.distance(), object.direction()))) {
                throw new IllegalArgumentException("recall: scene of cycle " + scene.cycle() + " uses another grid than "
                        + grid.describe() + " (object " + object.name() + " in cell " + object.cell()
                        + "); recall places remembered objects in the default grid only");
            }
        }
    }
}
