package org.scenes.plugins.field;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.scenes.api.EncodedMetric;
import org.scenes.api.MetricProvider;
import org.scenes.api.PackedMetric;
import org.scenes.api.PluginConfig;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.Side;
import org.scenes.api.TuneDimension;
import org.scenes.api.World;

/**
 * {@code field}: scenes compared by their world models ({@link World}, scenes converted with
 * {@code --world}), in field coordinates of the player's own frame rather than by what the view
 * showed: a weighted Euclidean distance over the player's position, the ball's offset from the
 * player, the ball's velocity, the body's direction (as a unit vector), stamina, the distance from
 * the ball to the nearest opponent the player knows of (weight 0 unless asked), plus a penalty
 * when the play modes differ (modes compared from the player's side: {@code kick_off_l} of a left
 * player equals {@code kick_off_r} of a right one), more when only one of them lets the players place
 * themselves (before a kick-off, after a goal), another when the ball is within kicking reach
 * in one scene only (what decides most of a player's actions), and another when the player is its
 * team's nearest to the ball (among the teammates its world model knows) in one scene only (who
 * runs for the ball and who keeps its place). With {@code ball-frame=body} the ball's offset
 * and velocity are turned into the body's frame (ahead, to the right) instead. A scene without a located world model is
 * {@code missing} away from every other; an unknown ball costs {@code missing} / 10.
 */
public final class FieldMetricProvider implements MetricProvider {
    /** The feature order of an encoding. */
    static final int X = 0;
    static final int Y = 1;
    static final int BALL_DX = 2;
    static final int BALL_DY = 3;
    static final int BALL_VX = 4;
    static final int BALL_VY = 5;
    static final int BODY_COS = 6;
    static final int BODY_SIN = 7;
    static final int STAMINA = 8;
    static final int OPPONENT = 9;
    static final int FEATURES = 10;
    /**
     * An opponent this far from the ball or farther (or none known) puts no pressure on it:
     * {@link #OPPONENT}'s distance is cut here, so an empty half and a crowded one differ by it at most.
     */
    static final double OPPONENT_FAR = 10;
    /** The default server's full stamina: stamina is compared as a share of it. */
    static final double STAMINA_MAX = 8000;
    /** The default player's kicking reach: player_size 0.3 + ball_size 0.085 + kickable_margin 0.7. */
    static final double KICKABLE = 1.085;

    @Override
    public String name() {
        return "field";
    }

    @Override
    public String description() {
        return "world-model features in field coordinates: own position, ball offset and velocity, body,"
                + " stamina, play mode (scenes converted with --world)";
    }

    @Override
    public Map<String, String> options() {
        Map<String, String> options = new LinkedHashMap<>();
        options.put("position-weight", "weight of the player's position, per metre (default 0.1)");
        options.put("ball-weight", "weight of the ball's offset from the player, per metre (default 1)");
        options.put("ball-velocity-weight", "weight of the ball's velocity, per metre per cycle (default 2)");
        options.put("body-weight", "weight of the body direction's unit vector (default 3)");
        options.put("stamina-weight", "weight of stamina as a share of 8000 (default 2)");
        options.put("opponent-weight", "weight of the distance from the ball to the nearest opponent the player knows"
                + " of, per metre, cut at " + (int) OPPONENT_FAR + " m (default 0)");
        options.put("play-mode-penalty", "added when the play modes differ (default 10)");
        options.put("placement-penalty", "added when one play mode lets the players place themselves with move"
                + " (before_kick_off, after a goal) and the other does not (default 0)");
        options.put("kickable-penalty", "added when the ball is within kicking reach (1.085 m, the default player's)"
                + " in one scene and not in the other (default 10)");
        options.put("chaser-penalty", "added when the player is its team's nearest to the ball (of the teammates it"
                + " knows) in one scene and not in the other (default 10)");
        options.put("ball-frame", "field: the ball's offset along the pitch's axes (default); body: turned into the"
                + " body's frame (ahead, to the right)");
        options.put("missing", "distance of a scene without a located world model (default 1000)");
        options.put("index", "true: search an exact k-d tree index; false: scan every scene (default true)");
        return options;
    }

    @Override
    public List<TuneDimension> tuneDimensions() {
        return List.of(TuneDimension.log("position-weight", 0.03, 0.1, 0.3, 1),
                TuneDimension.log("ball-weight", 0.3, 1, 3),
                TuneDimension.log("ball-velocity-weight", 0.5, 2, 8),
                TuneDimension.log("body-weight", 1, 3, 10),
                TuneDimension.log("stamina-weight", 0.5, 2, 8),
                TuneDimension.log("opponent-weight", 0.3, 1, 3, 10),
                TuneDimension.log("play-mode-penalty", 3, 10, 30),
                TuneDimension.linear("placement-penalty", 0, 30, 100),
                TuneDimension.log("kickable-penalty", 1, 3, 10, 30),
                TuneDimension.log("chaser-penalty", 1, 3, 10, 30));
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        double position = weight(config, "position-weight", 0.1);
        double ball = weight(config, "ball-weight", 1);
        double velocity = weight(config, "ball-velocity-weight", 2);
        double body = weight(config, "body-weight", 3);
        double stamina = weight(config, "stamina-weight", 2);
        double[] weights = new double[FEATURES];
        weights[X] = position;
        weights[Y] = position;
        weights[BALL_DX] = ball;
        weights[BALL_DY] = ball;
        weights[BALL_VX] = velocity;
        weights[BALL_VY] = velocity;
        weights[BODY_COS] = body;
        weights[BODY_SIN] = body;
        weights[STAMINA] = stamina;
        weights[OPPONENT] = weight(config, "opponent-weight", 0);
        String frame = config.option("ball-frame", "field");
        if (!frame.equals("field") && !frame.equals("body")) {
            throw new IllegalArgumentException("field: ball-frame must be field or body, not " + frame);
        }
        String index = config.option("index", "true");
        if (!index.equals("true") && !index.equals("false")) {
            throw new IllegalArgumentException("field: index must be true or false, not " + index);
        }
        return new FieldMetric(weights, new Penalties(weight(config, "play-mode-penalty", 10),
                weight(config, "placement-penalty", 0), weight(config, "kickable-penalty", 10),
                weight(config, "chaser-penalty", 10)), weight(config, "missing", 1000), frame.equals("body"),
                index.equals("true"));
    }

    private static double weight(PluginConfig config, String name, double fallback) {
        double value = config.doubleOption(name, fallback);
        if (!(value >= 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException("field: " + name + " must be a finite number of 0 or more, not " + value);
        }
        return value;
    }

    /**
     * A scene's features, each multiplied by its weight already; {@code mode} the play mode from
     * the player's side; null features for a scene without a located world.
     */
    record Features(double[] values, boolean ballKnown, String mode, boolean kickable, boolean chaser) {
        Features(double[] values, boolean ballKnown, String mode) {
            this(values, ballKnown, mode, false, false);
        }
    }

    /**
     * What two scenes add when they differ in play mode, in whether the mode is one where the players
     * place themselves, in the ball within reach, and in the team's nearest to the ball.
     */
    record Penalties(double playMode, double placement, double kickable, double chaser) {
    }

    /**
     * The play modes (from the player's side) in which the server lets every player {@code move}
     * itself: before a kick-off and after a goal. The clock stands, the ball is dead and the
     * teacher holds its kick-off place, turning to look around: a scene of play matched there runs
     * a player away from its place before the kick-off.
     */
    private static final Set<String> PLACEMENT_MODES = Set.of("before_kick_off", "goal_own", "goal_opp", "goal_l",
            "goal_r");

    static final class FieldMetric implements EncodedMetric<Features>, PackedMetric {
        private final double[] weights;
        private final Penalties penalties;
        private final double missing;
        private final boolean bodyFrame;
        private final boolean indexed;

        FieldMetric(double[] weights, Penalties penalties, double missing, boolean bodyFrame, boolean indexed) {
            this.weights = weights;
            this.penalties = penalties;
            this.missing = missing;
            this.bodyFrame = bodyFrame;
            this.indexed = indexed;
        }

        @Override
        public Features encode(Scene scene) {
            World w = scene.world();
            if (w == null || !w.located()) {
                return new Features(null, false, "");
            }
            double[] f = new double[FEATURES];
            f[X] = w.x();
            f[Y] = w.y();
            boolean ballKnown = w.ballKnown();
            double body = Double.isNaN(w.body()) ? 0 : Math.toRadians(w.body());
            if (ballKnown) {
                double dx = w.ballX() - w.x();
                double dy = w.ballY() - w.y();
                double vx = Double.isNaN(w.ballVx()) ? 0 : w.ballVx();
                double vy = Double.isNaN(w.ballVy()) ? 0 : w.ballVy();
                // in the body's frame: x ahead, y to the right (the server's directions turn towards +y)
                double cos = bodyFrame ? Math.cos(body) : 1;
                double sin = bodyFrame ? Math.sin(body) : 0;
                f[BALL_DX] = dx * cos + dy * sin;
                f[BALL_DY] = dy * cos - dx * sin;
                f[BALL_VX] = vx * cos + vy * sin;
                f[BALL_VY] = vy * cos - vx * sin;
            }
            f[BODY_COS] = Math.cos(body);
            f[BODY_SIN] = Math.sin(body);
            f[STAMINA] = Double.isNaN(w.stamina()) ? 1 : w.stamina() / STAMINA_MAX;
            f[OPPONENT] = ballKnown ? nearestOpponent(w) : OPPONENT_FAR;
            for (int i = 0; i < FEATURES; i++) {
                f[i] *= weights[i];
            }
            double ballDistance = w.ballDistance();
            return new Features(f, ballKnown, ownMode(w.playMode(), scene.observer().side()), ballDistance <= KICKABLE,
                    ballKnown && w.nearestOfItsTeamToBall());
        }

        /** The distance from the ball to the nearest opponent in the world model, at most {@link #OPPONENT_FAR}. */
        static double nearestOpponent(World w) {
            double nearest = OPPONENT_FAR;
            for (World.Player player : w.players()) {
                if (player.relation() == Relation.OPPONENT) {
                    nearest = Math.min(nearest, Math.hypot(player.x() - w.ballX(), player.y() - w.ballY()));
                }
            }
            return nearest;
        }

        /** The play mode with its side letter as seen from the player: {@code kick_off_own}, {@code goal_opp}. */
        static String ownMode(String mode, Side side) {
            int at = mode.lastIndexOf('_');
            if (side == null || at < 0 || at != mode.length() - 2) {
                return mode;
            }
            char letter = mode.charAt(at + 1);
            if (letter != 'l' && letter != 'r') {
                return mode;
            }
            return mode.substring(0, at) + (letter == side.letter() ? "_own" : "_opp");
        }

        @Override
        public PackedScenes pack(List<Scene> scenes) {
            return indexed ? FieldIndex.build(this, scenes) : null;
        }

        double missing() {
            return missing;
        }

        /** The sum of squares two located scenes differ by before their features: play mode, ball state, chaser. */
        double fixedCost(Features query, Features stored) {
            double sum = 0;
            if (!query.mode().equals(stored.mode())) {
                sum = penalties.playMode() * penalties.playMode();
                if (penalties.placement() > 0
                        && PLACEMENT_MODES.contains(query.mode()) != PLACEMENT_MODES.contains(stored.mode())) {
                    sum += penalties.placement() * penalties.placement();
                }
            }
            if (query.ballKnown() != stored.ballKnown()) {
                sum += missing * missing / 100;
            }
            if (query.kickable() != stored.kickable()) {
                sum += penalties.kickable() * penalties.kickable();
            }
            if (query.chaser() != stored.chaser()) {
                sum += penalties.chaser() * penalties.chaser();
            }
            return sum;
        }

        @Override
        public double distance(Features query, Features stored, double bound) {
            if (query.values() == null || stored.values() == null) {
                return query.values() == stored.values() ? 0 : missing;
            }
            double sum = fixedCost(query, stored);
            double limit = bound * bound;
            double[] a = query.values();
            double[] b = stored.values();
            for (int i = 0; i < FEATURES && sum <= limit; i++) {
                double d = a[i] - b[i];
                sum += d * d;
            }
            return Math.sqrt(sum);
        }
    }
}
