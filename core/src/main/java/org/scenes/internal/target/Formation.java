package org.scenes.internal.target;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.WeakHashMap;
import org.scenes.api.Action;
import org.scenes.api.Scene;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;

/**
 * Where the recorded player stood in play on for each place of the ball, its spot: the mean of its
 * positions over its scenes whose ball lay in the same {@link #CELL}-metre square or the eight
 * around it (as HELIOS base places its players by the ball's position). A player far from its spot
 * runs there unless it goes for the ball ({@link #keep}): the matched scenes come from a teacher
 * that is rarely far from its place, so they held no way back, and the imitators of HELIOS base
 * defended 6 to 7 metres higher than their teacher with the ball in their half. One per player
 * (it remembers whether it is on its way); the spots are made once per knowledge base.
 */
public final class Formation {
    /** Metres of the side of the squares of ball positions. */
    static final double CELL = 3;
    /** Scenes a spot needs from its square and the eight around it; fewer leave it unknown. */
    static final int SAMPLES = 10;
    /** Metres from its spot beyond which a player runs there. */
    static final double AWAY = 5;
    /** Metres from its spot at which a run there ends (less than {@link #AWAY}, so a run is not cut at once). */
    static final double BACK = 2;
    /** The squares' span: the pitch and the area around it where the ball can be. */
    private static final double HALF_X = 57;
    private static final double HALF_Y = 39;
    private static final int COLUMNS = (int) Math.ceil(2 * HALF_X / CELL);
    private static final int ROWS = (int) Math.ceil(2 * HALF_Y / CELL);
    private static final Map<KnowledgeBase, Formation> CACHE = new WeakHashMap<>();

    /** each square's spot, x then y; NaN where unknown */
    private final double[] spotX;
    private final double[] spotY;
    /** whether the previous decision ran to the spot */
    private boolean running;
    private long runs;

    private Formation(double[] spotX, double[] spotY) {
        this.spotX = spotX;
        this.spotY = spotY;
    }

    /** A player's formation from a knowledge base's played scenes; the spots are made once per knowledge base. */
    public static Formation of(KnowledgeBase knowledge) {
        Objects.requireNonNull(knowledge, "knowledge");
        Formation shared;
        synchronized (CACHE) {
            shared = CACHE.computeIfAbsent(knowledge, base -> of(base.scenes().subList(0, base.played())));
        }
        return new Formation(shared.spotX, shared.spotY);
    }

    /** The formation of these scenes: their players' mean positions in play on by the square of their ball. */
    static Formation of(List<Scene> scenes) {
        double[] sumX = new double[COLUMNS * ROWS];
        double[] sumY = new double[COLUMNS * ROWS];
        int[] count = new int[COLUMNS * ROWS];
        for (Scene scene : scenes) {
            World world = scene.world();
            if (world != null && world.located() && world.ballKnown() && "play_on".equals(world.playMode())) {
                int square = square(world.ballX(), world.ballY());
                sumX[square] += world.x();
                sumY[square] += world.y();
                count[square]++;
            }
        }
        double[] spotX = new double[COLUMNS * ROWS];
        double[] spotY = new double[COLUMNS * ROWS];
        for (int column = 0; column < COLUMNS; column++) {
            for (int row = 0; row < ROWS; row++) {
                double x = 0;
                double y = 0;
                int n = 0;
                for (int c = Math.max(0, column - 1); c <= Math.min(COLUMNS - 1, column + 1); c++) {
                    for (int r = Math.max(0, row - 1); r <= Math.min(ROWS - 1, row + 1); r++) {
                        x += sumX[c * ROWS + r];
                        y += sumY[c * ROWS + r];
                        n += count[c * ROWS + r];
                    }
                }
                spotX[column * ROWS + row] = n >= SAMPLES ? x / n : Double.NaN;
                spotY[column * ROWS + row] = n >= SAMPLES ? y / n : Double.NaN;
            }
        }
        return new Formation(spotX, spotY);
    }

    private static int square(double ballX, double ballY) {
        int column = (int) ((Math.max(-HALF_X, Math.min(HALF_X - 1e-9, ballX)) + HALF_X) / CELL);
        int row = (int) ((Math.max(-HALF_Y, Math.min(HALF_Y - 1e-9, ballY)) + HALF_Y) / CELL);
        return column * ROWS + row;
    }

    /** The recorded player's spot for a ball at ({@code ballX}, {@code ballY}); null when its scenes say too little. */
    double[] spot(double ballX, double ballY) {
        int square = square(ballX, ballY);
        return Double.isNaN(spotX[square]) ? null : new double[] {spotX[square], spotY[square]};
    }

    /**
     * {@code actions} (body action first), or a run to the player's spot for its ball in place of
     * the body action (the neck's stays) when, in play on with no kick chosen and the ball out of
     * reach, the player stands more than {@link #AWAY} metres from it (once on its way, until
     * {@link #BACK} metres near) and does not go for the ball: someone it knows of reaches the
     * ball first ({@link BallRace}).
     *
     * @param power the dash power to run with
     */
    public List<Action> keep(List<Action> actions, World own, double power) {
        double[] spot = Targets.mayRun(actions, own) ? spot(own.ballX(), own.ballY()) : null;
        running = spot != null
                && Math.hypot(own.x() - spot[0], own.y() - spot[1]) > (running ? BACK : AWAY)
                && BallRace.of(own).standing() != BallRace.Standing.FIRST;
        if (!running) {
            return actions;
        }
        runs++;
        return Targets.withBody(Targets.runTo(spot, own, power), actions);
    }

    /** Decisions that ran to the spot. */
    public long runs() {
        return runs;
    }
}
