package org.scenes.internal.world;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.scene.SceneFileReader;

/**
 * How far scenes' world models are from the truth a game log records: each scene with a world is
 * paired with the show of its cycle (cycles the clock stood still in, with several shows, are
 * left out: which one the player saw is not known) and its player's true position and body, and
 * the ball's, in the player's own frame. Errors are summed per kind as medians and 90th
 * percentiles.
 */
public final class WorldAccuracy {
    /** The truth of one cycle: the show, when it was the only one of its time. */
    private final Map<Integer, GameFrame> frames = new HashMap<>();
    private final Errors position = new Errors();
    private final Errors body = new Errors();
    private final Errors ball = new Errors();
    private final Errors ballSeen = new Errors();
    private final Errors ballVelocity = new Errors();
    private long scenes;
    private long unlocated;

    /** The errors of one kind: their median and 90th percentile. */
    public record Summary(long count, double median, double p90) {
    }

    /** Every kind of error, in metres and degrees. */
    public record Report(long scenes, long unlocated, Summary position, Summary body, Summary ball,
                         Summary ballSeen, Summary ballVelocity) {
    }

    /** The truth of one game log. */
    public WorldAccuracy(Path gameLog) throws IOException {
        Map<Integer, Integer> shows = new HashMap<>();
        GameLogReader.forEach(gameLog, frame -> {
            shows.merge(frame.time(), 1, Integer::sum);
            frames.put(frame.time(), frame);
        });
        shows.forEach((time, count) -> {
            if (count > 1) {
                frames.remove(time);
            }
        });
    }

    /** Adds the scenes of a scene file (those of players of this game). */
    public void add(Path sceneFile) {
        try (SceneFileReader reader = SceneFileReader.open(sceneFile)) {
            reader.forEachRemaining(this::add);
        }
    }

    /** Adds one scene. */
    public void add(Scene scene) {
        World world = scene.world();
        GameFrame frame = frames.get(scene.cycle());
        Observer observer = scene.observer();
        if (world == null || frame == null || observer.side() == null) {
            return;
        }
        PlayerState self = null;
        for (PlayerState state : frame.players()) {
            if (state.side() == observer.side() && state.unum() == observer.uniformNumber()) {
                self = state;
            }
        }
        if (self == null) {
            return;
        }
        scenes++;
        if (!world.located()) {
            unlocated++;
            return;
        }
        double sign = observer.side() == Side.RIGHT ? -1 : 1;
        position.add(Math.hypot(world.x() - sign * self.x(), world.y() - sign * self.y()));
        double trueBody = self.body() + (observer.side() == Side.RIGHT ? 180 : 0);
        body.add(Math.abs(Localisation.normalize(world.body() - trueBody)));
        if (world.ballKnown()) {
            GameFrame.BallState truth = frame.ball();
            double error = Math.hypot(world.ballX() - sign * truth.x(), world.ballY() - sign * truth.y());
            ball.add(error);
            if (world.ballAge() == 0) {
                ballSeen.add(error);
                ballVelocity.add(Math.hypot(world.ballVx() - sign * truth.vx(), world.ballVy() - sign * truth.vy()));
            }
        }
    }

    public Report report() {
        return new Report(scenes, unlocated, position.summary(), body.summary(), ball.summary(), ballSeen.summary(),
                ballVelocity.summary());
    }

    /** A growing list of errors. */
    private static final class Errors {
        private double[] values = new double[1024];
        private int size;

        void add(double value) {
            if (size == values.length) {
                values = Arrays.copyOf(values, size * 2);
            }
            values[size++] = value;
        }

        Summary summary() {
            if (size == 0) {
                return new Summary(0, Double.NaN, Double.NaN);
            }
            double[] sorted = Arrays.copyOf(values, size);
            Arrays.sort(sorted);
            return new Summary(size, quantile(sorted, 0.5), quantile(sorted, 0.9));
        }

        private static double quantile(double[] sorted, double q) {
            return sorted[(int) Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
        }
    }
}
