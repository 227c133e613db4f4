package org.scenes.internal.inference;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.world.ServerDefaults;

/**
 * The commands one player executed in one simulator step, from the game log's shows before and
 * after it: which ones from the command counters, their arguments by inverting rcssserver's models.
 * <ul>
 * <li>turn: the body turns by {@code moment (1 + r) / (1 + inertia_moment |v|)}, {@code r} uniform
 *     within {@code player_rand}: the moment is the turn times {@code 1 + inertia_moment |v|}, within
 *     {@code player_rand} of the moment;</li>
 * <li>dash (a player or ball that ran into another bounced back at a tenth of its speed: its velocity
 *     is turned back first): the stamina drops by the power (twice a negative one) and recovers by
 *     {@code recovery stamina_inc_max} (at most the capacity left): the power exactly while the stamina
 *     stays below its maximum; the direction is that of the acceleration
 *     {@code v' / player_decay - v} relative to the body (the velocity's noise bounds it); at full
 *     stamina the power comes from the acceleration's length, {@code effort power dir_rate dash_power_rate};</li>
 * <li>kick: the ball's acceleration {@code v' / ball_decay - v} (a ball that bounced off a player,
 *     reversed at a tenth of its speed, turned back; one cut to {@code ball_speed_max}, the full
 *     kick that ends on its velocity's ray) points in the kick's direction relative to the
 *     body, its length is {@code power kick_power_rate (1 - 0.25 dir_diff / 180 - 0.25 dist / kickable_margin)}
 *     with the ball's direction and distance from the kicker before the kick;</li>
 * <li>turn_neck: the neck angle's change (at the neck's limit, at least that); move: the position
 *     after (in the player's own coordinates); catch: the ball's direction from the body;
 *     tackle: the ball's acceleration's direction, else the ball's direction; change_view: the view after.</li>
 * </ul>
 * {@code say}, {@code pointto} and {@code attentionto} are counted by the server but their words are
 * not in a show: they are left out.
 */
final class CommandInference {
    /** One inferred command: arguments as the protocol orders them, with their bounds (NaN: not given). */
    record Command(CommandType type, double first, double second, double firstBound, double secondBound) {
        /** The command as a player writes it. */
        String text() {
            return switch (type) {
                case DASH, KICK, MOVE -> "(" + type.key() + " " + num(first) + " " + num(second) + ")";
                case CHANGE_VIEW -> "(change_view " + VIEWS[(int) first] + (second == 0 ? " low" : "") + ")";
                default -> "(" + type.key() + " " + num(first) + ")";
            };
        }

        /**
         * The value to three decimals without trailing zeros, as {@code String.format("%.3f")} rounds
         * (half up on {@link Double#toString}'s digits), {@code -0} as 0. From a thousandth to 10^7 in
         * magnitude, where the two agree (CommandTextTest), by {@link BigDecimal}: the formatter and
         * its regular expressions took a fifth of the Java time of converting a HELIOS game with
         * inferred commands.
         */
        static String num(double value) {
            double magnitude = Math.abs(value);
            if (magnitude == 0) {
                return "0";
            }
            String text;
            if (magnitude >= 1e-3 && magnitude < 1e7) {
                text = new BigDecimal(Double.toString(value)).setScale(3, RoundingMode.HALF_UP).stripTrailingZeros()
                        .toPlainString();
            } else {
                text = String.format(Locale.ROOT, "%.3f", value);
                text = text.contains(".") ? text.replaceAll("0+$", "").replaceAll("\\.$", "") : text;
            }
            return text.equals("-0") ? "0" : text;
        }
    }

    /** The commands of a player's step, or why the counters tell none (null when they do). */
    record Step(List<Command> commands, String irregular) {
        CommandType body() {
            for (Command command : commands) {
                if (command.type().body()) {
                    return command.type();
                }
            }
            return null;
        }

        String text() {
            StringBuilder text = new StringBuilder(64);
            for (Command command : commands) {
                text.append(command.text());
            }
            return text.toString();
        }
    }

    static final String[] VIEWS = {"narrow", "normal", "wide"};
    private static final double BALL_MOVED = 1e-3;

    private final ServerModel model;
    private final double playerRand;
    private final double ballDecay;
    private final double ballRand;
    private final double ballSize;
    private final double ballSpeedMax;
    private final double ballAccelMax;
    private final double staminaMax;
    private final double sideDashRate;
    private final double backDashRate;
    private final double dashAngleStep;
    private final double minMoment;
    private final double maxMoment;
    private final double minPower;
    private final double maxPower;
    private final double minDashPower;
    private final double maxDashPower;
    private final double maxNeckAngle;
    private final double minNeckAngle;
    private final double visibleAngle;

    CommandInference(ServerModel model) {
        this.model = model;
        playerRand = model.get("player_rand", 0.1);
        ballDecay = model.get("ball_decay", ServerDefaults.BALL_DECAY);
        ballRand = model.get("ball_rand", 0.05);
        ballSize = model.get("ball_size", ServerDefaults.BALL_SIZE);
        ballSpeedMax = model.get("ball_speed_max", 3);
        ballAccelMax = model.get("ball_accel_max", ServerDefaults.BALL_ACCEL_MAX);
        staminaMax = model.get("stamina_max", 8000);
        sideDashRate = model.get("side_dash_rate", 0.4);
        backDashRate = model.get("back_dash_rate", 0.7);
        dashAngleStep = Math.max(1e-6, model.get("dash_angle_step", 1));
        minMoment = model.get("minmoment", -ServerDefaults.MAX_MOMENT);
        maxMoment = model.get("maxmoment", ServerDefaults.MAX_MOMENT);
        minPower = model.get("minpower", -ServerDefaults.MAX_POWER);
        maxPower = model.get("maxpower", ServerDefaults.MAX_POWER);
        minDashPower = model.get("min_dash_power", 0);
        maxDashPower = model.get("max_dash_power", 100);
        minNeckAngle = model.get("minneckang", -ServerDefaults.MAX_NECK_ANGLE);
        maxNeckAngle = model.get("maxneckang", ServerDefaults.MAX_NECK_ANGLE);
        visibleAngle = model.get("visible_angle", 90);
    }

    /**
     * The commands player {@code a} (in show {@code before}) executed in the step to show
     * {@code after}, where it is {@code b}.
     */
    Step infer(GameFrame before, PlayerState a, GameFrame after, PlayerState b) {
        return infer(before, a, after, b, false);
    }

    /**
     * As {@link #infer(GameFrame, PlayerState, GameFrame, PlayerState)}; {@code shared} when another
     * player kicked or tackled in the same step: the ball's acceleration is the sum of theirs, a kick's
     * arguments are then bound by nothing.
     */
    Step infer(GameFrame before, PlayerState a, GameFrame after, PlayerState b, boolean shared) {
        PlayerState.Counts x = a.counts();
        PlayerState.Counts y = b.counts();
        int[] deltas = {y.kick() - x.kick(), y.dash() - x.dash(), y.turn() - x.turn(), y.catches() - x.catches(),
            y.move() - x.move(), y.tackle() - x.tackle(), y.turnNeck() - x.turnNeck(), y.changeView() - x.changeView()};
        String[] names = {"kick", "dash", "turn", "catch", "move", "tackle", "turn_neck", "change_view"};
        int body = 0;
        for (int i = 0; i < deltas.length; i++) {
            if (deltas[i] < 0) {
                return new Step(List.of(), names[i] + " count goes back from " + (count(x, i)) + " to " + count(y, i));
            }
            if (deltas[i] > 1) {
                return new Step(List.of(), names[i] + " count jumps by " + deltas[i]);
            }
            body += i < 6 ? deltas[i] : 0;
        }
        if (body > 1) {
            return new Step(List.of(), "two body commands counted in one step");
        }
        List<Command> commands = new ArrayList<>(3);
        if (deltas[0] == 1) {
            Command kick = kick(before, a, after);
            commands.add(shared ? new Command(CommandType.KICK, kick.first(), kick.second(), Double.POSITIVE_INFINITY,
                    180) : kick);
        } else if (deltas[1] == 1) {
            commands.add(dash(a, b));
        } else if (deltas[2] == 1) {
            commands.add(turn(a, b));
        } else if (deltas[3] == 1) {
            commands.add(catchBall(before, a));
        } else if (deltas[4] == 1) {
            commands.add(move(b));
        } else if (deltas[5] == 1) {
            commands.add(tackle(before, a, after));
        }
        if (deltas[6] == 1) {
            double moment = b.neck() - a.neck();
            boolean atLimit = Math.abs(b.neck() - maxNeckAngle) < 1e-6 || Math.abs(b.neck() - minNeckAngle) < 1e-6;
            commands.add(new Command(CommandType.TURN_NECK, moment, Double.NaN, atLimit ? Double.POSITIVE_INFINITY : 0.5,
                    Double.NaN));
        }
        if (deltas[7] == 1) {
            commands.add(changeView(b));
        }
        return new Step(commands, null);
    }

    private static int count(PlayerState.Counts c, int i) {
        return switch (i) {
            case 0 -> c.kick();
            case 1 -> c.dash();
            case 2 -> c.turn();
            case 3 -> c.catches();
            case 4 -> c.move();
            case 5 -> c.tackle();
            case 6 -> c.turnNeck();
            default -> c.changeView();
        };
    }

    Command turn(PlayerState a, PlayerState b) {
        double speed = Math.hypot(a.vx(), a.vy());
        double factor = 1 + model.type(a.type()).inertiaMoment() * speed;
        double turned = normalize(b.body() - a.body());
        double moment = clamp(turned * factor, minMoment, maxMoment);
        // a turn of more than 180 degrees (at full moment, standing, with noise) shows as one the other way
        double limit = Math.max(Math.abs(minMoment), Math.abs(maxMoment));
        double bound = Math.abs(moment) * playerRand / (1 - playerRand) + 0.001 * factor;
        if (Math.abs(turned) * factor > limit * (1 - playerRand)) {
            bound = Math.max(bound, limit * playerRand * 2);
        }
        return new Command(CommandType.TURN, moment, Double.NaN, bound, Double.NaN);
    }

    Command dash(PlayerState a, PlayerState b) {
        ServerModel.PlayerType type = model.type(a.type());
        // a player that ran into another bounces back at a tenth of its speed
        double bounce = bounced(a.x(), a.y(), b.x(), b.y(), b.vx(), b.vy()) ? -0.1 : 1;
        double accelX = b.vx() / (type.decay() * bounce) - a.vx();
        double accelY = b.vy() / (type.decay() * bounce) - a.vy();
        double accel = Math.hypot(accelX, accelY);
        double noise = playerRand * Math.hypot(a.vx() + accelX, a.vy() + accelY) * Math.sqrt(2);
        double direction = accel < 1e-4 ? 0 : normalize(Math.toDegrees(Math.atan2(accelY, accelX)) - a.body());
        direction = clamp(dashAngleStep * Math.rint(direction / dashAngleStep), model.get("min_dash_angle", -180),
                model.get("max_dash_angle", 180));
        double directionBound = accel <= noise ? 180 : Math.toDegrees(Math.asin(Math.min(1, noise / accel)));
        double recovered = Double.isNaN(b.recovery()) ? type.staminaIncMax() : b.recovery() * type.staminaIncMax();
        if (!Double.isNaN(a.capacity())) {
            recovered = Math.min(recovered, a.capacity());
        }
        double power;
        double powerBound;
        if (b.stamina() < staminaMax - 0.01) {
            double need = a.stamina() - b.stamina() + recovered;
            // a negative power costs twice its size: the acceleration against the body's direction tells it
            power = minDashPower < 0 && Math.abs(direction) > 90 && model.get("max_dash_angle", 180) == 0 ? -need / 2
                    : need;
            powerBound = 0.02 + (Double.isNaN(a.capacity()) ? 0 : 0.5);
        } else {
            // at full stamina the recovery hides the cost: the acceleration's length tells the power
            double rate = a.effort() * dirRate(direction) * type.dashPowerRate();
            power = rate <= 0 ? 0 : accel / rate;
            powerBound = rate <= 0 ? maxDashPower : noise / rate;
        }
        power = clamp(power, Math.min(0, minDashPower), maxDashPower);
        return new Command(CommandType.DASH, power, direction, powerBound, directionBound);
    }

    /** The share of a dash's power that acts in direction {@code dir} from the body. */
    double dirRate(double dir) {
        double abs = Math.abs(dir);
        return abs > 90 ? backDashRate - (backDashRate - sideDashRate) * (1 - (abs - 90) / 90)
                : sideDashRate + (1 - sideDashRate) * (1 - abs / 90);
    }

    Command kick(GameFrame before, PlayerState a, GameFrame after) {
        ServerModel.PlayerType type = model.type(a.type());
        GameFrame.BallState ball = before.ball();
        GameFrame.BallState next = after.ball();
        // a ball that ran into a player bounces back at a tenth of its speed
        double bounce = bounced(ball, next) ? -0.1 : 1;
        double accelX = next.vx() / (ballDecay * bounce) - ball.vx();
        double accelY = next.vy() / (ballDecay * bounce) - ball.vy();
        double accel = Math.hypot(accelX, accelY);
        if (accel < BALL_MOVED) {
            // the ball did not move: out of reach, or another player's kick met this one
            return new Command(CommandType.KICK, 0, 0, Double.POSITIVE_INFINITY, 180);
        }
        double toBall = Math.toDegrees(Math.atan2(ball.y() - a.y(), ball.x() - a.x()));
        double dirDiff = Math.abs(normalize(toBall - a.body()));
        double distance = Math.hypot(ball.x() - a.x(), ball.y() - a.y()) - type.playerSize() - ballSize;
        double rate = type.kickPowerRate() * (1 - 0.25 * dirDiff / 180 - 0.25 * Math.max(0, distance) / type.kickableMargin());
        double speed = Math.hypot(next.vx(), next.vy()) / ballDecay;
        if (bounce > 0 && speed > ballSpeedMax * (1 - ballRand) && rate > 0) {
            // the ball's speed was cut to its maximum, which turned its velocity: a kick of full power
            // (the likeliest to reach it) is the one whose acceleration from v lands on the velocity's ray
            double full = Math.min(rate * maxPower, ballAccelMax);
            double wx = next.vx() / (speed * ballDecay);
            double wy = next.vy() / (speed * ballDecay);
            double along = wx * ball.vx() + wy * ball.vy();
            double root = along * along - (ball.vx() * ball.vx() + ball.vy() * ball.vy()) + full * full;
            if (root >= 0) {
                double t = along + Math.sqrt(root);
                accelX = t * wx - ball.vx();
                accelY = t * wy - ball.vy();
                accel = Math.hypot(accelX, accelY);
            }
        }
        double direction = normalize(Math.toDegrees(Math.atan2(accelY, accelX)) - a.body());
        double power = rate <= 0 ? maxPower : clamp(accel / rate, minPower, maxPower);
        // rcssserver's two noises, each a vector of random direction: the kick's, up to kick_rand of the
        // power share times a rate of 0.5 to 1 for where the ball lay plus one for how fast it ran, and
        // the ball's, up to ball_rand of its new speed
        double positionRate = 0.5 + 0.25 * (dirDiff / 180 + Math.max(0, distance) / type.kickableMargin());
        double speedRate = 0.5 + 0.5 * Math.hypot(ball.vx(), ball.vy()) / (ballSpeedMax * ballDecay);
        double noise = type.kickRand() * Math.abs(power) / maxPower * (positionRate + speedRate)
                + ballRand * Math.hypot(ball.vx() + accelX, ball.vy() + accelY);
        double directionBound = accel <= noise ? 180 : Math.toDegrees(Math.asin(Math.min(1, noise / accel)));
        return new Command(CommandType.KICK, power, direction, rate <= 0 ? maxPower : noise / rate, directionBound);
    }

    /** Whether the ball moved one way and ends the step going the other: it ran into a player. */
    static boolean bounced(GameFrame.BallState ball, GameFrame.BallState next) {
        return bounced(ball.x(), ball.y(), next.x(), next.y(), next.vx(), next.vy());
    }

    /** Whether an object moved from (x, y) to (x2, y2) and ends the step with velocity (vx2, vy2) against that. */
    static boolean bounced(double x, double y, double x2, double y2, double vx2, double vy2) {
        double dx = x2 - x;
        double dy = y2 - y;
        return Math.hypot(dx, dy) > 0.05 && dx * vx2 + dy * vy2 < 0;
    }

    Command catchBall(GameFrame before, PlayerState a) {
        GameFrame.BallState ball = before.ball();
        double direction = normalize(Math.toDegrees(Math.atan2(ball.y() - a.y(), ball.x() - a.x())) - a.body());
        direction = clamp(direction, model.get("min_catch_angle", -90), model.get("max_catch_angle", 90));
        return new Command(CommandType.CATCH, direction, Double.NaN, 1, Double.NaN);
    }

    Command tackle(GameFrame before, PlayerState a, GameFrame after) {
        GameFrame.BallState ball = before.ball();
        GameFrame.BallState next = after.ball();
        double bounce = bounced(ball, next) ? -0.1 : 1;
        double accelX = next.vx() / (ballDecay * bounce) - ball.vx();
        double accelY = next.vy() / (ballDecay * bounce) - ball.vy();
        boolean moved = Math.hypot(accelX, accelY) > BALL_MOVED;
        double world = moved ? Math.atan2(accelY, accelX) : Math.atan2(ball.y() - a.y(), ball.x() - a.x());
        return new Command(CommandType.TACKLE, normalize(Math.toDegrees(world) - a.body()), Double.NaN,
                moved ? 10 : 180, Double.NaN);
    }

    static Command move(PlayerState b) {
        double sign = b.side() == Side.LEFT ? 1 : -1;
        return new Command(CommandType.MOVE, sign * b.x(), sign * b.y(), 0.01, 0.01);
    }

    Command changeView(PlayerState b) {
        double factor = b.viewWidth() / visibleAngle;
        // asynchronous cones are half, one and two visible angles; synchronous ones two thirds, four thirds and two
        int width = factor < 0.75 ? 0 : factor < 1.6 ? 1 : 2;
        return new Command(CommandType.CHANGE_VIEW, width, b.viewQuality() == 'l' ? 0 : 1, 0, 0);
    }

    static double normalize(double degrees) {
        double angle = degrees % 360;
        if (angle > 180) {
            angle -= 360;
        } else if (angle < -180) {
            angle += 360;
        }
        return angle;
    }

    private static double clamp(double value, double low, double high) {
        return Math.max(low, Math.min(high, value));
    }
}
