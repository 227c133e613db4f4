package org.scenes.internal.world;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
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
 * paired with the show of its cycle while the clock runs (at 0 before kick-off, after goals and at half
 * time the clock stands and the player goes on turning and moving over steps the game log shows
 * once or not at all, so the show is not the state it saw; cycles with several shows, and cycles
 * of which a player has several scenes, are left out too), and its player's true position and body, and
 * the ball's, in the player's own frame. Errors are summed per kind as medians and 90th
 * percentiles.
 */
public final class WorldAccuracy {
    /** The truth of one cycle: the show, when it was the only one of its time. */
    private final Map<Integer, GameFrame> frames = new HashMap<>();
    /** The errors of each scene, kept until {@link #report} knows which cycles had one scene only. */
    private final List<Measured> measured = new ArrayList<>();
    /** Scenes per player and cycle: a player with several scenes of a cycle lived through a standing clock. */
    private final Map<String, Integer> scenesOfCycle = new HashMap<>();

    private record Measured(String key, boolean located, double position, double body, double ball, double ballSeen,
                            double ballVelocity) {
    }

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
            String mode = frames.get(time).playMode();
            if (count > 1 || time == 0 || mode.equals("before_kick_off") || mode.startsWith("goal_") || mode.equals("half_time")) {
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
        String key = observer.side().letter() + observer.uniformNumber() + ":" + scene.cycle();
        scenesOfCycle.merge(key, 1, Integer::sum);
        if (!world.located()) {
            measured.add(new Measured(key, false, 0, 0, Double.NaN, Double.NaN, Double.NaN));
            return;
        }
        double sign = observer.side() == Side.RIGHT ? -1 : 1;
        double trueBody = self.body() + (observer.side() == Side.RIGHT ? 180 : 0);
        double ballError = Double.NaN;
        double seenError = Double.NaN;
        double velocityError = Double.NaN;
        if (world.ballKnown()) {
            GameFrame.BallState truth = frame.ball();
            ballError = Math.hypot(world.ballX() - sign * truth.x(), world.ballY() - sign * truth.y());
            if (world.ballAge() == 0) {
                seenError = ballError;
                velocityError = Math.hypot(world.ballVx() - sign * truth.vx(), world.ballVy() - sign * truth.vy());
            }
        }
        measured.add(new Measured(key, true, Math.hypot(world.x() - sign * self.x(), world.y() - sign * self.y()),
                Math.abs(Localisation.normalize(world.body() - trueBody)), ballError, seenError, velocityError));
    }

    public Report report() {
        Errors position = new Errors();
        Errors body = new Errors();
        Errors ball = new Errors();
        Errors ballSeen = new Errors();
        Errors ballVelocity = new Errors();
        long scenes = 0;
        long unlocated = 0;
        for (Measured m : measured) {
            if (scenesOfCycle.get(m.key()) > 1) {
                continue;
            }
            scenes++;
            if (!m.located()) {
                unlocated++;
                continue;
            }
            position.add(m.position());
            body.add(m.body());
            ball.addKnown(m.ball());
            ballSeen.addKnown(m.ballSeen());
            ballVelocity.addKnown(m.ballVelocity());
        }
        return new Report(scenes, unlocated, position.summary(), body.summary(), ball.summary(), ballSeen.summary(),
                ballVelocity.summary());
    }

    /** A growing list of errors. */
    private static final class Errors {
        private double[] values = new double[1024];
        private int size;

        void addKnown(double value) {
            if (!Double.isNaN(value)) {
                add(value);
            }
        }

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
