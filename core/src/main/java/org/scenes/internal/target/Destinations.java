package org.scenes.internal.target;

import static org.scenes.internal.vision.Landmarks.PITCH_HALF_LENGTH;
import static org.scenes.internal.vision.Landmarks.PITCH_HALF_WIDTH;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.WeakHashMap;
import org.scenes.api.ActionType;
import org.scenes.api.Neighbour;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.world.ServerDefaults;

/**
 * Where each stored scene's player went in the next {@link #AHEAD} cycles, read from the same
 * player's later scene in the knowledge base. A neighbour that stood near the deciding player
 * lends the point it ran to (a formation spot); one that stood elsewhere (the neighbours of a
 * metric that ignores position, such as {@code ball-goal}, stand anywhere) lends its displacement,
 * added to the deciding player's position (scenes of one recorded player lie
 * in cycle order, one sequence after another). Unknown when that scene is missing, unlocated, or
 * a move or another play mode lies between (a kick-off's jump is no run).
 */
public final class Destinations {
    /** How far ahead the destination is read: a second of play, the span of one run to a spot. */
    static final int AHEAD = 10;
    /** Later scenes looked at past {@link #AHEAD} cycles when the exact one is missing (sparse vision). */
    private static final int SLACK = 5;
    private static final Map<KnowledgeBase, Destinations> CACHE = new WeakHashMap<>();

    /**
     * A player that reached its ball within this many cycles was running to the ball (an
     * interception takes longer than the destination's second when the ball is far).
     */
    static final int CHASE = 30;

    /** A player this near its ball at some cycle of the run reached the ball: a run to the ball (kicking reach). */
    static final double AT_BALL = ServerDefaults.KICKABLE_AREA;

    /** A neighbour that stood this near the deciding player lends its end point, a farther one its displacement. */
    static final double NEAR = 10;

    /**
     * A neighbour that stood this near its ball, when the deciding player knows its own, lends its
     * end point relative to its ball, placed at the deciding player's ball: near the ball a
     * player's run answers the ball (pressing, covering), not a spot of the pitch.
     */
    static final double BALL_NEAR = 8;

    /** How far inside the field lines a run ends at the latest, metres (a run stops within a metre of its end). */
    static final double LINE_INSET = 1;

    /** Bins of {@link #chaseRate}, one per cycle the player needs to reach its ball; the last holds every later one. */
    static final int CHASE_BINS = 40;
    /** Scenes a bin needs before its rate is trusted over the neighbours' share. */
    static final int CHASE_SAMPLES = 30;

    /** where each scene's player stood, and where it was {@link #AHEAD} cycles later (NaN: unknown) */
    private final double[] fromX;
    private final double[] fromY;
    private final double[] x;
    private final double[] y;
    /** where each scene's player believed the ball was (NaN: unknown) */
    private final double[] ballX;
    private final double[] ballY;
    /** whether the player reached the ball on the way: it ran to the ball, wherever that was */
    private final boolean[] toBall;
    /**
     * How often the recorded players reached the ball within {@link #CHASE} cycles, by their
     * standing in the race to it ({@link BallRace.Standing}'s ordinal) and the cycles they needed
     * to reach it: NaN for a bin of fewer than {@link #CHASE_SAMPLES} scenes.
     */
    private final double[][] chaseRate;

    private Destinations(double[] fromX, double[] fromY, double[] x, double[] y, double[] ballX, double[] ballY,
                         boolean[] toBall, double[][] chaseRate) {
        this.fromX = fromX;
        this.fromY = fromY;
        this.x = x;
        this.y = y;
        this.ballX = ballX;
        this.ballY = ballY;
        this.toBall = toBall;
        this.chaseRate = chaseRate;
    }

    /** The destinations of a knowledge base's scenes, computed once per knowledge base. */
    public static Destinations of(KnowledgeBase knowledge) {
        Objects.requireNonNull(knowledge, "knowledge");
        synchronized (CACHE) {
            return CACHE.computeIfAbsent(knowledge, base -> of(base.scenes(), base.played()));
        }
    }

    /** Whether the destinations of this knowledge base are already made (and {@link #of} returns at once). */
    public static boolean made(KnowledgeBase knowledge) {
        synchronized (CACHE) {
            return CACHE.containsKey(knowledge);
        }
    }

    /** The destinations of scenes all played in stored order. */
    static Destinations of(List<Scene> scenes) {
        return of(scenes, scenes.size());
    }

    /**
     * The destinations of scenes in stored order, the first {@code played} of them played (the
     * others, DAgger's labels, have none); each scene is read once (a knowledge base decodes on
     * every read).
     */
    static Destinations of(List<Scene> scenes, int played) {
        int n = scenes.size();
        int[] cycle = new int[n];
        Observer[] observer = new Observer[n];
        String[] mode = new String[n];
        boolean[] moved = new boolean[n];
        double[] atX = new double[n];
        double[] atY = new double[n];
        double[] ballX = new double[n];
        double[] ballY = new double[n];
        BallRace[] race = new BallRace[n];
        int i = 0;
        for (Scene scene : scenes) {
            World world = scene.world();
            cycle[i] = scene.cycle();
            observer[i] = scene.observer();
            mode[i] = world == null ? null : world.playMode();
            moved[i] = scene.actionType() == ActionType.MOVE;
            atX[i] = world == null ? Double.NaN : world.x();
            atY[i] = world == null ? Double.NaN : world.y();
            ballX[i] = world == null ? Double.NaN : world.ballX();
            ballY[i] = world == null ? Double.NaN : world.ballY();
            race[i] = BallRace.of(world);
            i++;
        }
        double[] x = new double[n];
        double[] y = new double[n];
        boolean[] toBall = new boolean[n];
        Arrays.fill(x, Double.NaN);
        Arrays.fill(y, Double.NaN);
        for (i = 0; i < played; i++) {
            if (mode[i] == null || Double.isNaN(atX[i])) {
                continue;
            }
            boolean reachedBall = false;
            boolean placed = false;
            for (int j = i + 1; j < played; j++) {
                int gap = cycle[j] - cycle[i];
                if (gap < 0 || gap > (placed ? CHASE : AHEAD) + SLACK || !Objects.equals(observer[j], observer[i])
                        || !mode[i].equals(mode[j]) || moved[j]) {
                    break;
                }
                reachedBall |= Math.hypot(ballX[j] - atX[j], ballY[j] - atY[j]) <= AT_BALL;
                if (!placed && gap >= AHEAD) {
                    x[i] = atX[j];
                    y[i] = atY[j];
                    placed = true;
                }
                if (placed && (reachedBall || gap >= CHASE)) {
                    break;
                }
            }
            toBall[i] = placed && reachedBall;
        }
        return new Destinations(atX, atY, x, y, ballX, ballY, toBall, chaseRates(x, race, toBall));
    }

    private static double[][] chaseRates(double[] x, BallRace[] race, boolean[] toBall) {
        int standings = BallRace.Standing.values().length;
        int[][] runs = new int[standings][CHASE_BINS];
        int[][] all = new int[standings][CHASE_BINS];
        for (int i = 0; i < x.length; i++) {
            if (Double.isNaN(x[i]) || race[i] == null) {
                continue;
            }
            int standing = race[i].standing().ordinal();
            int bin = Math.min(CHASE_BINS - 1, race[i].cycles());
            all[standing][bin]++;
            runs[standing][bin] += toBall[i] ? 1 : 0;
        }
        double[][] rates = new double[standings][CHASE_BINS];
        for (int s = 0; s < standings; s++) {
            for (int bin = 0; bin < CHASE_BINS; bin++) {
                rates[s][bin] = all[s][bin] < CHASE_SAMPLES ? Double.NaN : runs[s][bin] / (double) all[s][bin];
            }
        }
        return rates;
    }

    /**
     * How often the recorded players who stood so in the race to their ball reached it within
     * {@link #CHASE} cycles; NaN when too few stood so, or {@code race} is null.
     */
    double chaseRate(BallRace race) {
        return race == null ? Double.NaN
                : chaseRate[race.standing().ordinal()][Math.min(CHASE_BINS - 1, race.cycles())];
    }

    /**
     * Where to run for these neighbours, from {@code own}'s position: when most of those with a
     * destination ran to the ball (reached it within {@link #CHASE} cycles), or, where enough
     * recorded scenes stood as the player stands in the race to its ball ({@link BallRace}), most of
     * those ({@link #chaseRate}), {@code ball} (where
     * the deciding player can reach its own ball, null when it does not know one); else the mean
     * of their end points relative to their ball placed at the player's own (those within
     * {@link #BALL_NEAR} metres of their ball, when the player knows its ball), their end points
     * (those within {@link #NEAR} metres of the player) and their displacements from its
     * position (the others); null when none has one or the player's
     * position is unknown. (A neighbour found as a transform's image, such as a mirrored scene,
     * counts as its stored scene.)
     */
    public double[] target(List<Neighbour> nearest, World own, double[] ball) {
        return target(nearest, own, ball, new Steering());
    }

    /**
     * The same for a player that remembers its previous choice: a chase goes on while at least
     * a third of the neighbours ran to the ball ({@link Steering}).
     */
    public double[] target(List<Neighbour> nearest, World own, double[] ball, Steering steering) {
        if (own == null || !own.located()) {
            return null;
        }
        double sumX = 0;
        double sumY = 0;
        int count = 0;
        int ballRuns = 0;
        boolean ownBall = own.ballKnown();
        for (Neighbour neighbour : nearest) {
            int i = neighbour.index();
            if (i >= 0 && i < x.length && !Double.isNaN(x[i])) {
                if (ownBall && Math.hypot(fromX[i] - ballX[i], fromY[i] - ballY[i]) <= BALL_NEAR) {
                    sumX += own.ballX() + x[i] - ballX[i];
                    sumY += own.ballY() + y[i] - ballY[i];
                } else if (Math.hypot(fromX[i] - own.x(), fromY[i] - own.y()) <= NEAR) {
                    sumX += x[i];
                    sumY += y[i];
                } else {
                    sumX += own.x() + x[i] - fromX[i];
                    sumY += own.y() + y[i] - fromY[i];
                }
                count++;
                if (toBall[i]) {
                    ballRuns++;
                }
            }
        }
        if (count == 0) {
            return null;
        }
        // the teacher's own rate where enough of its scenes stood so: k neighbours are too few to tell
        double rate = chaseRate(BallRace.of(own));
        if (steering.chase(Double.isNaN(rate) ? ballRuns / (double) count : rate) && ball != null) {
            return onPitch(ball);
        }
        return onPitch(steering.spot(new double[] {sumX / count, sumY / count}));
    }

    /**
     * The point moved inside the field lines by {@link #LINE_INSET}: a ball rolling into the goal
     * or out, or an offset from a ball by the line, is not followed beyond it (imitators of HELIOS
     * base stood behind their own goal line in 3 % of play on, HELIOS base in none).
     */
    static double[] onPitch(double[] point) {
        return new double[] {Targets.clamp(point[0], PITCH_HALF_LENGTH - LINE_INSET),
            Targets.clamp(point[1], PITCH_HALF_WIDTH - LINE_INSET)};
    }
}
