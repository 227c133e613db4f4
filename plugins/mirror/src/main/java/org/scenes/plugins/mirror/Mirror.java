package org.scenes.plugins.mirror;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.scenes.api.Action;
import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.World;

/**
 * The mirror image of a scene: the same situation with left and right exchanged, as if the
 * pitch were reflected across its long axis. Every direction the scene holds (of objects, their
 * direction changes, players' body, head and pointing directions) is negated; flag and line
 * names exchange top and bottom ({@code f t l 30} and {@code f b l 30}, goal posts {@code f g r t}
 * and {@code f g r b}), which is what lies to the player's left and right after the reflection;
 * goals, the ball and players keep their names. Commands are mirrored too: turn moments,
 * neck angles, kick, dash and catch directions are negated, a move's y is negated. Cells are
 * those of the mirrored directions in the default grid (other grids are refused). A world model
 * is reflected across the pitch's long axis.
 */
public final class Mirror {
    /** Mirrored flag and line names, made once each: mirror:match mirrors every query and what it finds. */
    private static final Map<String, String> SWAPPED = new ConcurrentHashMap<>();

    private Mirror() {
    }

    public static Scene of(Scene scene) {
        List<SeenObject> objects = new ArrayList<>(scene.objects().size());
        for (SeenObject object : scene.objects()) {
            objects.add(mirror(object));
        }
        List<Action> actions = scene.actions().stream().map(Mirror::mirror).toList();
        return new Scene(scene.cycle(), scene.observer(), objects, actions,
                scene.previous() == null ? null : of(scene.previous()), scene.seeAge(),
                scene.world() == null ? null : mirror(scene.world()));
    }

    /** The world model reflected across the pitch's long axis: y, velocities across and directions negated. */
    static World mirror(World w) {
        List<World.Player> players = w.players().stream()
                .map(p -> new World.Player(p.relation(), p.unum(), p.x(), -p.y(), p.age())).toList();
        return new World(w.x(), -w.y(), -w.body(), -w.neck(), w.vx(), -w.vy(), w.stamina(), w.effort(), w.age(),
                w.ballX(), -w.ballY(), w.ballVx(), -w.ballVy(), w.ballAge(), players, w.playMode(), w.ownScore(),
                w.opponentScore());
    }

    static SeenObject mirror(SeenObject object) {
        String name = object.kind() == ObjectKind.FLAG || object.kind() == ObjectKind.LINE
                ? SWAPPED.computeIfAbsent(object.name(), Mirror::swapTopAndBottom) : object.name();
        return new SeenObject(object.kind(), name, object.team(), object.uniformNumber(), object.goalie(),
                object.relation(), object.distance(), -object.direction(), object.distanceChange(),
                -object.directionChange(), -object.bodyFacing(), -object.headFacing(), -object.pointingDirection(),
                object.mark(), mirror(object.cell(), object), object.confidence());
    }

    /** The column counted from the other side; refuses a grid that is not symmetric about the view's middle. */
    private static Cell mirror(Cell cell, SeenObject object) {
        Grid grid = Grid.DEFAULT;
        if (!Double.isNaN(object.distance()) && !Double.isNaN(object.direction())
                && !cell.equals(grid.cell(object.distance(), object.direction()))) {
            throw new IllegalArgumentException("mirror: object " + object.name() + " in cell " + cell
                    + " is not in the default grid " + grid.describe() + "; mirror supports the default grid only");
        }
        // a direction on a column boundary belongs to one side only, so place the mirrored direction itself
        return Double.isNaN(object.direction()) ? new Cell(grid.columns() - 1 - cell.column(), cell.row())
                : grid.cell(object.distance(), -object.direction());
    }

    /** Exchanges the words {@code t} and {@code b} of a flag or line name (upper case too). */
    static String swapTopAndBottom(String name) {
        String[] words = name.split(" ");
        for (int i = 1; i < words.length; i++) {
            switch (words[i]) {
                case "t" -> words[i] = "b";
                case "b" -> words[i] = "t";
                case "T" -> words[i] = "B";
                case "B" -> words[i] = "T";
                default -> { }
            }
        }
        return String.join(" ", words);
    }

    static Action mirror(Action action) {
        return switch (action.type()) {
            case TURN, TURN_NECK, CATCH -> new Action(action.type(), -action.first(), action.second());
            case KICK, DASH -> new Action(action.type(), action.first(), -action.second());
            case MOVE -> new Action(action.type(), action.first(), -action.second());
            default -> action;
        };
    }
}
