package org.scenes.internal.target;

import static org.scenes.internal.vision.VisionNumbers.normalize;
import static org.scenes.internal.world.ServerDefaults.BALL_ACCEL_MAX;
import static org.scenes.internal.world.ServerDefaults.BALL_DECAY;
import static org.scenes.internal.world.ServerDefaults.BALL_SIZE;
import static org.scenes.internal.world.ServerDefaults.INERTIA_MOMENT;
import static org.scenes.internal.world.ServerDefaults.KICKABLE_AREA;
import static org.scenes.internal.world.ServerDefaults.KICKABLE_MARGIN;
import static org.scenes.internal.world.ServerDefaults.KICK_POWER_RATE;
import static org.scenes.internal.world.ServerDefaults.MAX_MOMENT;
import static org.scenes.internal.world.ServerDefaults.MAX_NECK_ANGLE;
import static org.scenes.internal.world.ServerDefaults.MAX_POWER;
import static org.scenes.internal.world.ServerDefaults.PLAYER_SIZE;
import static org.scenes.internal.world.ServerDefaults.TACKLE_DIST;
import static org.scenes.internal.world.ServerDefaults.TACKLE_EXPONENT;
import static org.scenes.internal.world.ServerDefaults.TACKLE_WIDTH;

import java.util.ArrayList;
import java.util.List;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.World;

/**
 * Re-expresses a recorded player's actions as what they achieved in the field frame, and reaches
 * the same from another player's state with the soccer server's motion models (default player
 * type): a turn becomes the body direction it produced (a turn with no ball in view stays a turn
 * by its moment: a search); a dash the field direction it drove along (turning first when the body
 * is more than {@link #DASH_TOLERANCE} degrees off it) or, given where the neighbours ran
 * ({@link Destinations}), a run there ({@link #goTo}); a kick the
 * ball velocity it produced, solved for power and direction from where the ball lies; a neck turn
 * the field direction the head came to look; a catch is aimed at the ball. A direction that pointed
 * at the ball or the opponent goal is re-aimed at them ({@link #anchored}). Moves and tackles stay
 * as recorded. Where either world model lacks what a target needs (no position, no ball), the
 * recorded command is sent as it is.
 *
 * <p>Both worlds are in the player's own frame (its team attacking towards +x), so a scene of
 * either team targets the same field direction for both.
 */
public final class Targets {
    /** A dash is sent as recorded when the body is this close to the recorded dash's field direction. */
    static final double DASH_TOLERANCE = 45;
    /**
     * A run to a point dashes when the body is this close to the point's bearing, else turns first:
     * a dash 45 degrees off closes only 0.7 of its length, and a runner after a rolling ball falls behind.
     */
    static final double RUN_TOLERANCE = 15;
    /** A direction more than this far off is behind: turned to one way only ({@link #turnAngle}). */
    static final double BEHIND = 150;
    /** Cycles of the ball's course searched for an interception point. */
    static final int INTERCEPT_HORIZON = 50;
    /** Metres a player runs per cycle at full power: the default type's dash model at its steady speed. */
    static final double RUN_SPEED = 1.0;
    /** A destination this near is reached: the player then does what the chosen scene's player did. */
    static final double ARRIVED = 1;
    /** A turn of the body by less than this many degrees is taken as facing its target already. */
    static final double REACHED = 5;
    /** A recorded direction this close to the ball or the goal is taken as aimed at it. */
    static final double ANCHOR = 10;
    /** The opponent goal's centre in the player's own frame. */
    static final double GOAL_X = 52.5;
    /**
     * A tackle is sent only where the player's world model gives it at least this chance: failed
     * or not, a tackle holds the player for ten cycles, and imitators of HELIOS base tackled 30
     * times as often as their teacher, from two to four metres.
     */
    static final double TACKLE_CHANCE = 0.5;

    private Targets() {
    }

    /**
     * The actions that reach from {@code query}'s state what {@code recorded} achieved from
     * {@code chosen}'s: the body action first, then the neck action, as recorded.
     *
     * @param recorded the chosen scene's actions (body and neck)
     * @param chosen the scene that holds them, or null
     * @param query the deciding player's scene
     */
    public static List<Action> reach(List<Action> recorded, Scene chosen, Scene query) {
        return reach(recorded, chosen, query, null, Double.NaN);
    }

    /**
     * The same, with the point the neighbours ran to: a dash or turn then steers the player to
     * {@code destination} ({@link #goTo}) rather than copying one neighbour's heading.
     *
     * @param destination the mean destination of the neighbours ({@link Destinations}), or null
     * @param power the dash power to run with, NaN for the recorded dash's or the full power
     */
    public static List<Action> reach(List<Action> recorded, Scene chosen, Scene query, double[] destination,
                                     double power) {
        if (chosen == null || recorded.isEmpty()) {
            return recorded;
        }
        World donor = chosen.world();
        World own = query.world();
        if (donor == null || own == null || !donor.located() || !own.located()) {
            return recorded;
        }
        double donorBall = ballAngle(chosen);
        double ownBall = ballAngle(query);
        double donorBodyAfter = donor.body();
        double ownBodyAfter = own.body();
        List<Action> reached = new ArrayList<>(recorded.size());
        for (Action action : recorded) {
            boolean run = destination != null && (action.type() == ActionType.DASH || action.type() == ActionType.TURN);
            Action mine = action.type() == ActionType.TURN_NECK
                    ? neck(action, donor, donorBodyAfter, donorBall, own, ownBodyAfter, ownBall)
                    : run ? goTo(destination, own, runPower(action, power), body(action, chosen, donorBall, own, ownBall))
                    : body(action, chosen, donorBall, own, ownBall);
            if (action.type() == ActionType.TURN) {
                donorBodyAfter = donor.body() + turned(action.first(), donor);
            }
            if (mine.type() == ActionType.TURN) {
                ownBodyAfter = own.body() + turned(mine.first(), own);
            }
            reached.add(mine);
        }
        return List.copyOf(reached);
    }

    private static Action body(Action action, Scene chosen, double donorBall, World own, double ownBall) {
        World donor = chosen.world();
        return switch (action.type()) {
            // a turn without the ball in view is a search: its target is the turn itself
            case TURN -> !seesBall(chosen) ? action
                    : turnTo(anchored(donor.body() + turned(action.first(), donor), donor, donorBall, own, ownBall), own);
            case DASH -> dash(action, donor, donorBall, own, ownBall);
            case KICK -> kick(action, donor, own);
            case CATCH -> Double.isNaN(ownBall) ? action : Action.catchBall(normalize(ownBall));
            default -> action;
        };
    }

    /**
     * The ball's direction from the body: as the scene's see shows it, else as the world model
     * remembers it (so a target aimed at the ball stays so while the head looks away); NaN when
     * neither knows it.
     */
    static double ballAngle(Scene scene) {
        World world = scene.world();
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL && !object.remembered()) {
                return normalize(object.direction() + (Double.isNaN(world.neck()) ? 0 : world.neck()));
            }
        }
        return world.ballKnown()
                ? normalize(bearing(world.ballX() - world.x(), world.ballY() - world.y()) - world.body())
                : Double.NaN;
    }

    /** Whether the scene's see shows the ball. */
    private static boolean seesBall(Scene scene) {
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL && !object.remembered()) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether the body action of {@code reached} (actions made by {@link #reach} for {@code query})
     * achieves nothing: a turn of less than {@link #REACHED} degrees, the body already facing its target.
     */
    public static boolean alreadyReached(List<Action> reached, Scene query) {
        if (reached.isEmpty() || reached.get(0).type() != ActionType.TURN || query.world() == null) {
            return false;
        }
        return Math.abs(turned(reached.get(0).first(), query.world())) < REACHED;
    }

    /**
     * Whether the body action of {@code reached} can achieve nothing where {@code query}'s world
     * model puts the ball: a kick with the ball out of kicking reach, a tackle with the ball
     * unknown or its chance ({@link #tackleChance}) below {@link #TACKLE_CHANCE}. A kick with the
     * ball unknown is not judged.
     */
    public static boolean futile(List<Action> reached, Scene query) {
        World own = query.world();
        if (reached.isEmpty() || own == null || !own.located()) {
            return false;
        }
        return switch (reached.get(0).type()) {
            case KICK -> own.ballKnown() && kickRate(own) <= 0;
            case TACKLE -> !own.ballKnown() || tackleChance(own) < TACKLE_CHANCE;
            default -> false;
        };
    }

    /** The chance that a tackle succeeds with the ball where {@code world} puts it (rcssserver's tackle model). */
    static double tackleChance(World world) {
        double dx = world.ballX() - world.x();
        double dy = world.ballY() - world.y();
        double body = Math.toRadians(world.body());
        double ahead = dx * Math.cos(body) + dy * Math.sin(body);
        double aside = -dx * Math.sin(body) + dy * Math.cos(body);
        if (ahead <= 0) {
            return 0;
        }
        double failure = Math.pow(ahead / TACKLE_DIST, TACKLE_EXPONENT)
                + Math.pow(Math.abs(aside) / TACKLE_WIDTH, TACKLE_EXPONENT);
        return Math.max(0, 1 - failure);
    }

    /**
     * Where the player can first reach its ball's course (the server's ball decay; a run at the
     * default player's top speed after one turn), the ball's resting point when it cannot within
     * {@link #INTERCEPT_HORIZON} cycles; null when its world model knows no ball or no position.
     */
    public static double[] intercept(World world) {
        if (world == null || !world.located() || !world.ballKnown()) {
            return null;
        }
        int cycles = reachCycles(world.x(), world.y(), world, INTERCEPT_HORIZON);
        double vx = velocity(world.ballVx());
        double vy = velocity(world.ballVy());
        double bx = world.ballX();
        double by = world.ballY();
        for (int t = 0; t < cycles; t++) {
            bx += vx;
            by += vy;
            vx *= BALL_DECAY;
            vy *= BALL_DECAY;
        }
        return new double[] {bx, by};
    }

    /**
     * The cycles a player at ({@code x}, {@code y}) needs to reach the course of the ball of
     * {@code world} (the server's ball decay; a run at the default player's top speed after one
     * turn), {@code limit} when it cannot within fewer.
     */
    static int reachCycles(double x, double y, World world, int limit) {
        double vx = velocity(world.ballVx());
        double vy = velocity(world.ballVy());
        double bx = world.ballX();
        double by = world.ballY();
        for (int t = 0; t < limit; t++) {
            if (Math.hypot(bx - x, by - y) <= reach(t)) {
                return t;
            }
            bx += vx;
            by += vy;
            vx *= BALL_DECAY;
            vy *= BALL_DECAY;
        }
        return limit;
    }

    /** How far from where it stands a player reaches a ball in {@code cycles}: one turn, then {@link #RUN_SPEED} a cycle. */
    static double reach(int cycles) {
        return Math.max(0, cycles - 1) * RUN_SPEED + KICKABLE_AREA;
    }

    private static double runPower(Action action, double power) {
        if (!Double.isNaN(power)) {
            return power;
        }
        return action.type() == ActionType.DASH ? action.first() : MAX_POWER;
    }

    /**
     * Whether a run may take the place of the body action of {@code actions}: in play on, with no
     * kick chosen, where {@code own} knows its position and the ball, out of its kicking reach.
     */
    static boolean mayRun(List<Action> actions, World own) {
        return !actions.isEmpty() && actions.get(0).type() != ActionType.KICK && own != null && own.located()
                && own.ballKnown() && "play_on".equals(own.playMode()) && own.ballDistance() > KICKABLE_AREA;
    }

    /** {@code actions} (body action first) with {@code body} in place of their body action; the neck's stays. */
    static List<Action> withBody(Action body, List<Action> actions) {
        List<Action> replaced = new ArrayList<>(actions.size());
        replaced.add(body);
        replaced.addAll(actions.subList(1, actions.size()));
        return List.copyOf(replaced);
    }

    /** A run to {@code point} at {@code power} ({@link #goTo}); once there, a turn to face it. */
    public static Action runTo(double[] point, World own, double power) {
        return goTo(point, own, power, turnTo(bearing(point[0] - own.x(), point[1] - own.y()), own));
    }

    /**
     * Steers towards {@code destination}: a turn when the body is off its bearing by more than the
     * larger of {@link #RUN_TOLERANCE} and the angle that misses it by {@link #ARRIVED} metres,
     * else a dash at {@code power}; {@code arrived} once within {@link #ARRIVED} metres.
     */
    static Action goTo(double[] destination, World own, double power, Action arrived) {
        double dx = destination[0] - own.x();
        double dy = destination[1] - own.y();
        double distance = Math.hypot(dx, dy);
        if (distance < ARRIVED) {
            return arrived;
        }
        double off = normalize(bearing(dx, dy) - own.body());
        double tolerance = Math.max(RUN_TOLERANCE, Math.toDegrees(Math.asin(Math.min(1, ARRIVED / distance))));
        if (Math.abs(off) > tolerance) {
            return Action.turn(clamp(turnAngle(off) * (1 + INERTIA_MOMENT * speed(own)), MAX_MOMENT));
        }
        return Action.dash(power);
    }

    /**
     * The way to turn by {@code off} degrees: a direction nearly behind is turned to clockwise
     * (positive) whichever side the estimate puts it, so turns of a moving player (which cover
     * only part of the angle) do not alternate between left and right on a noisy estimate.
     */
    static double turnAngle(double off) {
        return Math.abs(off) > BEHIND && off < 0 ? off + 360 : off;
    }

    /** The turn that brings {@code own}'s body to {@code direction} (as near as one turn can). */
    static Action turnTo(double direction, World own) {
        double moment = turnAngle(normalize(direction - own.body())) * (1 + INERTIA_MOMENT * speed(own));
        return Action.turn(clamp(moment, MAX_MOMENT));
    }

    private static Action dash(Action action, World donor, double donorBall, World own, double ownBall) {
        // the dash drives along the body plus its direction: the same body gives the same way
        double body = anchored(donor.body(), donor, donorBall, own, ownBall);
        if (Math.abs(normalize(body - own.body())) <= DASH_TOLERANCE) {
            return action;
        }
        return turnTo(body, own);
    }

    /** A kick that gives the ball the velocity the recorded kick gave it, from where the ball lies for {@code own}. */
    private static Action kick(Action action, World donor, World own) {
        double donorRate = kickRate(donor);
        double ownRate = kickRate(own);
        if (Double.isNaN(donorRate) || Double.isNaN(ownRate) || ownRate <= 0) {
            return Action.kick(action.first(), normalize(donor.body() + action.second() - own.body()));
        }
        double[] wanted = kickedBall(action, donor, donorRate);
        double wantedX = wanted[0];
        double wantedY = wanted[1];
        // the ball's new course, aimed again at the goal when the recorded one was
        double course = anchoredToGoal(bearing(wantedX, wantedY), donor.ballX(), donor.ballY(), own.ballX(), own.ballY());
        double speed = Math.hypot(wantedX, wantedY);
        wantedX = speed * Math.cos(Math.toRadians(course));
        wantedY = speed * Math.sin(Math.toRadians(course));
        double neededX = wantedX - velocity(own.ballVx());
        double neededY = wantedY - velocity(own.ballVy());
        double power = Math.min(Math.hypot(neededX, neededY) / ownRate, MAX_POWER);
        return Action.kick(power, normalize(bearing(neededX, neededY) - own.body()));
    }

    /**
     * The ball's velocity right after {@code kick} by the player of {@code kicker} (the server's kick
     * model: the power times {@code rate}, at most {@code BALL_ACCEL_MAX}, along the
     * body plus the kick's direction, added to the ball's velocity), before the ball's decay.
     */
    static double[] kickedBall(Action kick, World kicker, double rate) {
        double accel = Math.min(Math.max(kick.first(), 0) * rate, BALL_ACCEL_MAX);
        double direction = Math.toRadians(kicker.body() + kick.second());
        return new double[] {velocity(kicker.ballVx()) + accel * Math.cos(direction),
            velocity(kicker.ballVy()) + accel * Math.sin(direction)};
    }

    /** The turn_neck that looks where the recorded head looked, within the neck's range. */
    private static Action neck(Action action, World donor, double donorBody, double donorBall, World own,
                               double ownBody, double ownBall) {
        double donorNeck = Double.isNaN(donor.neck()) ? 0 : donor.neck();
        double ownNeck = Double.isNaN(own.neck()) ? 0 : own.neck();
        // the ball's bearings after this cycle's body turns
        double looked = anchored(donorBody + clamp(donorNeck + action.first(), MAX_NECK_ANGLE), donor,
                donorBall - (donorBody - donor.body()), own, ownBall - (ownBody - own.body()));
        double neck = clamp(normalize(looked - ownBody), MAX_NECK_ANGLE);
        return Action.turnNeck(neck - ownNeck);
    }

    /**
     * A field direction of the recorded player re-aimed for {@code own}: one that pointed at the
     * ball (within {@link #ANCHOR} degrees; {@code donorBall} and {@code ownBall} are the ball's
     * directions from each body) points at {@code own}'s ball with the same offset, one
     * that pointed at the opponent goal's centre at that goal; any other stays a field direction.
     */
    static double anchored(double direction, World donor, double donorBall, World own, double ownBall) {
        if (!Double.isNaN(donorBall) && !Double.isNaN(ownBall)) {
            double offset = normalize(direction - (donor.body() + donorBall));
            if (Math.abs(offset) <= ANCHOR) {
                return own.body() + ownBall + offset;
            }
        }
        return anchoredToGoal(direction, donor.x(), donor.y(), own.x(), own.y());
    }

    /** A direction from ({@code fromX}, {@code fromY}) re-aimed from ({@code toX}, {@code toY}) when it pointed at the goal. */
    private static double anchoredToGoal(double direction, double fromX, double fromY, double toX, double toY) {
        if (Double.isNaN(fromX) || Double.isNaN(toX)) {
            return direction;
        }
        double offset = normalize(direction - bearing(GOAL_X - fromX, -fromY));
        return Math.abs(offset) <= ANCHOR ? bearing(GOAL_X - toX, -toY) + offset : direction;
    }

    /** The body's turn for a moment at the player's speed. */
    static double turned(double moment, World world) {
        return moment / (1 + INERTIA_MOMENT * speed(world));
    }

    /**
     * The share of kick power that reaches the ball where it lies (the server's kick model), or
     * NaN when the ball's position is unknown; at most zero out of reach.
     */
    static double kickRate(World world) {
        if (!world.ballKnown()) {
            return Double.NaN;
        }
        double dx = world.ballX() - world.x();
        double dy = world.ballY() - world.y();
        double gap = Math.max(Math.hypot(dx, dy) - PLAYER_SIZE - BALL_SIZE, 0);
        double angle = Math.abs(normalize(bearing(dx, dy) - world.body()));
        return KICK_POWER_RATE * (1 - 0.25 * angle / 180 - 0.25 * gap / KICKABLE_MARGIN);
    }

    private static double speed(World world) {
        double speed = Math.hypot(world.vx(), world.vy());
        return Double.isNaN(speed) ? 0 : speed;
    }

    /** A velocity component, 0 where unknown. */
    static double velocity(double component) {
        return Double.isNaN(component) ? 0 : component;
    }

    /** The field direction of (dx, dy), degrees. */
    static double bearing(double dx, double dy) {
        return Math.toDegrees(Math.atan2(dy, dx));
    }

    /** {@code value} within [-limit, limit]. */
    static double clamp(double value, double limit) {
        return Math.max(-limit, Math.min(limit, value));
    }
}
