package org.scenes.internal.target;

import static org.scenes.internal.vision.VisionNumbers.normalize;
import static org.scenes.internal.world.ServerDefaults.MAX_NECK_ANGLE;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.WeakHashMap;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Scene;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;

/**
 * Keeps the ball as fresh in the player's world model as the teacher kept it. HELIOS base's
 * players had seen their ball at most three cycles before in 98.5 % of their play-on scenes; its
 * imitators, whose heads look where the chosen scene's head looked, in 40 %, and a third of the
 * time had not seen it for over ten cycles: a defender facing where the ball had stopped stood
 * there while it rolled past. When the ball is older than the teacher's was in {@link #SHARE} of
 * its play-on scenes, the neck turns the head at it (as near as the neck goes), in place of the
 * chosen scene's gaze. Where the head then shows no ball, the world model forgets it, and the
 * player searches ({@link #search}): the teacher's scenes hardly ever lack a ball (0.15 % of
 * HELIOS base's play on), so the nearest of them are no search, and its imitators, matching them,
 * went without a ball for 6 % of play on, one of them for 148 cycles in a row, running out of
 * the pitch.
 */
public final class BallWatch {
    /** The share of the teacher's play-on scenes (with a ball known) whose ball was at most the limit old. */
    static final double SHARE = 0.95;
    /** A watch that never overrules: the teacher's scenes hold no ball to learn from. */
    static final BallWatch NEVER = new BallWatch(Integer.MAX_VALUE);
    private static final Map<KnowledgeBase, BallWatch> CACHE = new WeakHashMap<>();
    /**
     * Degrees a searching player turns its body a cycle: rcssserver's synchronous sees show 60
     * degrees a cycle at every width (60 each cycle, 120 every second, 180 every third), so with
     * the head straight the sees of a search leave no gap and go round in six cycles.
     */
    static final double SEARCH_TURN = 60;
    /** Play modes with no ball to look for: before a half starts, after a goal (the players place themselves), after the game. */
    private static final Set<String> NO_BALL = Set.of("before_kick_off", "goal_l", "goal_r", "time_over");

    private final int limit;

    private BallWatch(int limit) {
        this.limit = limit;
    }

    /** The watch of a knowledge base's played scenes, computed once per knowledge base. */
    public static BallWatch of(KnowledgeBase knowledge) {
        Objects.requireNonNull(knowledge, "knowledge");
        synchronized (CACHE) {
            return CACHE.computeIfAbsent(knowledge, base -> of(base.scenes().subList(0, base.played())));
        }
    }

    /** Whether the watch of this knowledge base is already made (and {@link #of} returns at once). */
    public static boolean made(KnowledgeBase knowledge) {
        synchronized (CACHE) {
            return CACHE.containsKey(knowledge);
        }
    }

    /** The watch of these scenes: the age that {@link #SHARE} of their play-on balls did not exceed. */
    static BallWatch of(List<Scene> scenes) {
        int[] ages = new int[scenes.size()];
        int count = 0;
        for (Scene scene : scenes) {
            World world = scene.world();
            if (world != null && world.ballKnown() && world.ballAge() >= 0 && world.playMode().equals("play_on")) {
                ages[count++] = world.ballAge();
            }
        }
        if (count == 0) {
            return NEVER;
        }
        Arrays.sort(ages, 0, count);
        return new BallWatch(ages[(int) Math.ceil(SHARE * count) - 1]);
    }

    /** Cycles the ball may go unseen before the head turns to it. */
    public int limit() {
        return limit;
    }

    /**
     * {@code actions} (body action first, then the neck's), with the neck turned to look at the
     * ball after this cycle's turn of the body and the ball's next step, when {@code own}'s ball is
     * older than {@link #limit}; as they are otherwise, or when the world model knows no ball or
     * position.
     */
    public List<Action> watch(List<Action> actions, World own) {
        if (!stale(own)) {
            return actions;
        }
        double body = bodyAfter(actions, own);
        List<Action> watched = new ArrayList<>(actions.size() + 1);
        for (Action action : actions) {
            if (action.type() != ActionType.TURN_NECK) {
                watched.add(action);
            }
        }
        double head = Targets.clamp(ballBearing(own, body), MAX_NECK_ANGLE);
        watched.add(Action.turnNeck(head - (Double.isNaN(own.neck()) ? 0 : own.neck())));
        return List.copyOf(watched);
    }

    /**
     * Whether {@code own}'s ball, older than {@link #limit}, lies where a head turned as far as the
     * neck goes still sees nothing of it with a view of {@code viewAngle} degrees, once the body has
     * done {@code actions}: behind the player, where only a wider view shows it.
     */
    public boolean beyondView(List<Action> actions, World own, double viewAngle) {
        return stale(own) && Math.abs(ballBearing(own, bodyAfter(actions, own))) > MAX_NECK_ANGLE + viewAngle / 2;
    }

    /**
     * A search in place of {@code actions} when {@code own} knows where it stands but no ball in a
     * game under way: the body turns by {@link #SEARCH_TURN} degrees (as far as one turn goes at
     * its speed) and the head looks straight ahead, so each see shows another part of the pitch;
     * {@code actions} as they are otherwise, and when they place the player ({@code move}).
     */
    public static List<Action> search(List<Action> actions, World own) {
        if (!searching(own) || actions.stream().anyMatch(action -> action.type() == ActionType.MOVE)) {
            return actions;
        }
        List<Action> search = new ArrayList<>(2);
        search.add(Targets.turnTo(own.body() + SEARCH_TURN, own));
        if (!Double.isNaN(own.neck()) && own.neck() != 0) {
            search.add(Action.turnNeck(-own.neck()));
        }
        return List.copyOf(search);
    }

    /** Whether {@code own} knows where it stands but not where the ball is, in a game under way. */
    private static boolean searching(World own) {
        return own != null && own.located() && !own.ballKnown() && !NO_BALL.contains(own.playMode());
    }

    /** Whether {@code own} knows where it stands and holds a ball older than {@link #limit}. */
    private boolean stale(World own) {
        return own != null && own.located() && own.ballKnown() && own.ballAge() > limit;
    }

    /** The body direction once the turn among {@code actions} is done. */
    private static double bodyAfter(List<Action> actions, World own) {
        double body = own.body();
        for (Action action : actions) {
            if (action.type() == ActionType.TURN) {
                body += Targets.turned(action.first(), own);
            }
        }
        return body;
    }

    /** The ball's direction after its next step, relative to {@code body}. */
    private static double ballBearing(World own, double body) {
        double dx = own.ballX() + Targets.velocity(own.ballVx()) - Targets.velocity(own.vx()) - own.x();
        double dy = own.ballY() + Targets.velocity(own.ballVy()) - Targets.velocity(own.vy()) - own.y();
        return normalize(Targets.bearing(dx, dy) - body);
    }
}
