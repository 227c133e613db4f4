package org.scenes.simulator;

import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Consumer;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.protocol.See;
import org.scenes.simulator.teacher.Teachers;

/**
 * Scenes without a game, as many as a benchmark wants: each one an independent random moment of
 * an 11 v 11 Krislet game, seen and labelled by the same code as real data. A moment places the
 * ball anywhere on the pitch, the other 21 players gathered round it (Krislet players all chase
 * the ball) and the observer at a distance and facing drawn to match the recorded Krislet games
 * (ball seen in about 95 % of scenes, straight ahead in about 72 %, kickable in 0.5 %); the
 * simulator's {@link Vision} writes the version 9 {@code see} (quantisation, view cone, objects
 * sensed behind, fading team and number), core's {@link MessageParser} and
 * {@link SceneConverter#seenObjects} turn it into objects as the converter does, and the classic
 * Krislet's rules choose the action from that see.
 *
 * <p>Streaming and deterministic: the same seed gives the same scenes in the same order, and a
 * shorter run is a prefix of a longer one. Nothing is kept between scenes, so a million scenes
 * cost only what the sink keeps.
 */
public final class SyntheticScenes {
    static final String HOME = "Home";
    static final String AWAY = "Away";
    static final int PLAYERS_PER_SIDE = 11;
    /** Cycles of a game: scene cycles count 1 to this, then start again. */
    static final int GAME_CYCLES = 6000;
    /** Scenes with the ball within Krislet's kickable metre (0.2 to 0.4 % in the recorded games). */
    static final double KICKABLE_SHARE = 0.005;
    /** Scenes whose observer looks straight at the ball, so Krislet dashes (66 to 75 % recorded). */
    static final double FACING_BALL_SHARE = 0.72;
    /**
     * Scenes whose observer has the ball in view but off centre, so Krislet turns to it; the rest
     * look anywhere (ball seen but not ahead in about 22 % of recorded scenes, not seen in 4 to 10 %).
     */
    static final double BALL_IN_VIEW_SHARE = 0.22;
    /** Mean of the ball's distance beyond 1 m, exponential: median near 11 m, 90 % within 33 m as recorded. */
    static final double BALL_DISTANCE_MEAN = 14;
    /** Standard deviation (metres, per axis) of the other players' spread round the ball. */
    static final double CROWD_SPREAD = 12;
    /** Top speeds drawn for players and the ball (metres per cycle). */
    static final double PLAYER_SPEED = 0.6;
    static final double BALL_SPEED = 1.2;

    private final SplittableRandom random;
    private final Grid grid;
    private final World world;
    private final Vision vision;
    private final Physics physics;
    private final MessageParser parser = new MessageParser();
    private final Observer[] observers = new Observer[2 * PLAYERS_PER_SIDE];
    private int cycle;

    private SyntheticScenes(long seed, Grid grid) {
        this.random = new SplittableRandom(seed);
        this.grid = grid;
        this.world = new World(ServerParams.DEFAULT, seed);
        for (Side side : new Side[] {Side.LEFT, Side.RIGHT}) {
            String team = side == Side.LEFT ? HOME : AWAY;
            for (int unum = 1; unum <= PLAYERS_PER_SIDE; unum++) {
                world.add(team, side, unum);
                observers[world.players.size() - 1] = new Observer(team, side, unum);
            }
        }
        this.vision = new Vision(world);
        this.physics = new Physics(world);
    }

    /**
     * Hands {@code count} scenes, one at a time, to {@code sink}; objects' cells are in {@code grid}.
     */
    public static void generate(long seed, int count, Grid grid, Consumer<Scene> sink) {
        generate(seed, count, 1, grid, sink);
    }

    /**
     * As {@link #generate(long, int, Grid, Consumer)}, but each drawn moment is followed for
     * {@code run} consecutive cycles of the same observer: its Krislet command takes effect and the
     * world moves one step before the next scene, so a scene's predecessor is the one a cycle
     * earlier, as in a game (what memory configurations compare). A run of 1 gives the same scenes
     * as the other method.
     */
    public static void generate(long seed, int count, int run, Grid grid, Consumer<Scene> sink) {
        if (count < 0) {
            throw new IllegalArgumentException("scene count must not be negative, not " + count);
        }
        if (run < 1) {
            throw new IllegalArgumentException("a run is at least 1 scene long, not " + run);
        }
        SyntheticScenes scenes = new SyntheticScenes(seed, grid);
        if (run > 1) {
            scenes.world.mode = PlayMode.PLAY_ON; // so dashes move the observer
        }
        for (int i = 0; i < count; i++) {
            sink.accept(i % run == 0 ? scenes.next() : scenes.following());
        }
    }

    /** The observer and its last command while a run lasts. */
    private int seat;
    private Action last;

    /** The same observer a cycle later: its last command applied, then one step of motion for everything. */
    private Scene following() {
        Player self = world.players.get(seat);
        switch (last.type()) {
            case TURN -> physics.turn(self, last.first());
            case DASH -> physics.dash(self, last.first());
            case KICK -> physics.kick(self, last.first(), last.second());
            default -> {
            }
        }
        physics.step();
        cycle = cycle % GAME_CYCLES + 1;
        world.time = cycle;
        return seen(self, observers[seat]);
    }

    private Scene next() {
        cycle = cycle % GAME_CYCLES + 1;
        world.time = cycle;
        seat = random.nextInt(world.players.size());
        Player self = world.players.get(seat);
        Observer observer = observers[seat];

        Ball ball = world.ball;
        ball.place(uniform(ServerParams.PITCH_HALF_LENGTH), uniform(ServerParams.PITCH_HALF_WIDTH));
        setVelocity(ball, random.nextDouble() * 360, random.nextDouble() * BALL_SPEED);
        for (Player other : world.players) {
            if (other != self) {
                other.place(onPitch(ball.x + random.nextGaussian() * CROWD_SPREAD, ServerParams.PITCH_HALF_LENGTH),
                        onPitch(ball.y + random.nextGaussian() * CROWD_SPREAD, ServerParams.PITCH_HALF_WIDTH));
                other.body = uniform(180);
                other.neck = 0; // Krislet never turns its neck
                setVelocity(other, other.body, random.nextDouble() * PLAYER_SPEED);
            }
        }
        placeObserver(self, ball);
        return seen(self, observer);
    }

    /** What the observer sees now, with the command the classic Krislet answers it with. */
    private Scene seen(Player self, Observer observer) {
        See see = (See) parser.parse(vision.see(self));
        String command = Teachers.krisletCommand(see, observer.side());
        last = ((PlayerCommand) parser.parse(command)).toAction();
        return new Scene(cycle, observer, SceneConverter.seenObjects(see, observer, grid), List.of(last), null, 0,
                truth(self, observer.side()));
    }

    /**
     * The observer's true state as a world model in its own frame (the right team's turned by 180
     * degrees): what a perfect localisation would give, so world-model metrics can be measured too.
     */
    private org.scenes.api.World truth(Player self, Side side) {
        double sign = side == Side.LEFT ? 1 : -1;
        Ball ball = world.ball;
        return new org.scenes.api.World(sign * self.x, sign * self.y,
                Numbers.normalize(self.body + (side == Side.LEFT ? 0 : 180)), self.neck, sign * self.vx,
                sign * self.vy, self.stamina, self.effort, 0, sign * ball.x, sign * ball.y, sign * ball.vx,
                sign * ball.vy, 0, List.of(), world.mode.word, 0, 0);
    }

    /** At a distance from the ball, within the pitch's margin, looking at it or anywhere. */
    private void placeObserver(Player self, Ball ball) {
        double distance = random.nextDouble() < KICKABLE_SHARE ? 0.3 + 0.7 * random.nextDouble()
                : 1 - BALL_DISTANCE_MEAN * Math.log(1 - random.nextDouble());
        double limitX = ServerParams.PITCH_HALF_LENGTH + ServerParams.PITCH_MARGIN;
        double limitY = ServerParams.PITCH_HALF_WIDTH + ServerParams.PITCH_MARGIN;
        double x = 0;
        double y = 0;
        // A few bearings until one keeps the observer on the ground; far draws end clamped.
        for (int attempt = 0; attempt < 8; attempt++) {
            double bearing = Math.toRadians(uniform(180));
            x = ball.x + distance * Math.cos(bearing);
            y = ball.y + distance * Math.sin(bearing);
            if (Math.abs(x) <= limitX && Math.abs(y) <= limitY) {
                break;
            }
        }
        self.place(onPitch(x, limitX), onPitch(y, limitY));
        double towardsBall = Math.toDegrees(Math.atan2(ball.y - self.y, ball.x - self.x));
        double facing = random.nextDouble();
        self.body = facing < FACING_BALL_SHARE ? towardsBall
                : facing < FACING_BALL_SHARE + BALL_IN_VIEW_SHARE ? towardsBall + uniform(ServerParams.DEFAULT.visibleAngle() / 2)
                : uniform(180);
        self.neck = 0;
        setVelocity(self, self.body, random.nextDouble() * PLAYER_SPEED);
    }

    private double uniform(double halfRange) {
        return (random.nextDouble() * 2 - 1) * halfRange;
    }

    private static double onPitch(double value, double limit) {
        return Math.max(-limit, Math.min(limit, value));
    }

    private static void setVelocity(MovingObject object, double directionDegrees, double speed) {
        double radians = Math.toRadians(directionDegrees);
        object.vx = speed * Math.cos(radians);
        object.vy = speed * Math.sin(radians);
    }
}
