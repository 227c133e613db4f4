package org.scenes.simulator;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import org.scenes.api.Side;

/** Everything on the pitch at one moment: ball, players, clock, play mode and score. */
final class World {
    /** New clients stand just outside the top touch line until they move, like on the real server's bench. */
    static final double BENCH_Y = ServerParams.PITCH_HALF_WIDTH + 3;
    /** Players in a fixed order whatever order they connected in: left team first, by number. */
    static final Comparator<Player> ORDER = Comparator.comparing((Player p) -> p.side).thenComparingInt(p -> p.unum);

    final ServerParams params;
    final Random random;
    final Ball ball = new Ball();
    final List<Player> players = new ArrayList<>();
    int time;
    PlayMode mode = PlayMode.BEFORE_KICK_OFF;
    /** The side awarded the current restart (kick-off, kick-in, corner or goal kick). */
    Side restartSide = Side.LEFT;
    /** The side that touched the ball last, null before the first kick. */
    Side lastTouch;
    int scoreLeft;
    int scoreRight;

    World(ServerParams params, long seed) {
        this.params = params;
        this.random = new Random(seed);
    }

    Player add(String team, Side side, int unum) {
        return add(team, side, unum, false);
    }

    Player add(String team, Side side, int unum, boolean goalie) {
        Player player = new Player(team, side, unum, goalie, params.staminaMax());
        // Off the pitch until the client moves it, like the real server's bench.
        player.place(-3.0 * unum * (side == Side.LEFT ? 1 : -1), -BENCH_Y);
        players.add(player);
        players.sort(ORDER);
        return player;
    }

    void remove(Player player) {
        players.remove(player);
    }

    /** Uniform noise in [-range, range]. */
    double noise(double range) {
        return range == 0 ? 0 : (random.nextDouble() * 2 - 1) * range;
    }

    /**
     * The server's noise vector: a length uniform in [0, maxLength] in a uniform direction
     * (not uniform on each axis), as {x, y}.
     */
    double[] polarNoise(double maxLength) {
        if (maxLength == 0) {
            return ZERO;
        }
        double length = random.nextDouble() * maxLength;
        double angle = (random.nextDouble() * 2 - 1) * Math.PI;
        return new double[] {length * Math.cos(angle), length * Math.sin(angle)};
    }

    private static final double[] ZERO = {0, 0};
}
