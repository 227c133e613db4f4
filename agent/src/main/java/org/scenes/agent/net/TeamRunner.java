package org.scenes.agent.net;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.scenes.simulator.BrainFactory;

/**
 * A team on a soccer server: N players in this JVM, a thread each, every brain made by one
 * factory (an imitation factory shares its recognizer read-only, with a selector and transforms
 * per player). Players connect one after another, so the server numbers them in order and the
 * first is the goalie when asked ({@code --goalie}), else the one whose brain asks for it (an
 * imitator of a recorded goalie, {@link BrainFactory#goalie}); a player that cannot connect stops the others from being
 * started. A player that fails is reported at once and in the end; the others play on.
 */
public final class TeamRunner {
    /** Extra time, beyond the connect timeout, a player's thread gets to report its init answer. */
    private static final long CONNECT_GRACE_MILLIS = 1000;
    /** How long {@link #stopAndAwait} waits for the players' goodbyes. */
    private static final long STOP_WAIT_MILLIS = 2000;

    private final ClientOptions options;
    private final int players;
    private final BrainFactory brains;
    private final long seed;
    private final Consumer<String> notices;
    private final List<LivePlayer> started = new ArrayList<>();
    private final List<Thread> threads = new ArrayList<>();
    private volatile boolean stopping;

    /**
     * @param players how many players, 1 to 11 (1 with a reconnect)
     * @param seed seeds each brain's random source (player i gets {@code seed + i})
     * @param notices one-line messages for the user; called from the players' threads
     */
    public TeamRunner(ClientOptions options, int players, BrainFactory brains, long seed, Consumer<String> notices) {
        this.options = Objects.requireNonNull(options, "options");
        if (players < 1 || players > 11) {
            throw new IllegalArgumentException("a team has 1 to 11 players, not " + players);
        }
        if (options.reconnect() > 0 && players != 1) {
            throw new IllegalArgumentException("a reconnect replaces one player, so give 1 player, not " + players);
        }
        this.players = players;
        this.brains = Objects.requireNonNull(brains, "brains");
        this.seed = seed;
        Consumer<String> target = Objects.requireNonNull(notices, "notices");
        this.notices = message -> {
            synchronized (this) {
                target.accept(message);
            }
        };
    }

    /** Connects the players, plays until every one has stopped, and returns their reports in order. */
    public List<PlayerReport> play() throws InterruptedException {
        for (int i = 0; i < players && !stopping; i++) {
            LivePlayer player = new LivePlayer(options, brains.create(options.team(), new Random(seed + i)),
                    options.goalie() ? i == 0 : brains.goalie(i + 1), notices);
            Thread thread = new Thread(player, options.team() + "-player-" + (i + 1));
            synchronized (started) {
                started.add(player);
                threads.add(thread);
            }
            thread.start();
            if (!player.awaitAnswer(options.connectTimeout().toMillis() + CONNECT_GRACE_MILLIS, TimeUnit.MILLISECONDS)) {
                break;
            }
        }
        for (Thread thread : threads()) {
            thread.join();
        }
        List<PlayerReport> reports = new ArrayList<>();
        for (LivePlayer player : players()) {
            reports.add(player.report());
        }
        return reports;
    }

    /** Asks every player to say {@code (bye)} and stop; returns at once. */
    public void stop() {
        stopping = true;
        for (LivePlayer player : players()) {
            player.stop();
        }
    }

    /** {@link #stop}, then waits a little for the goodbyes to go out (for a shutdown hook). */
    public void stopAndAwait() {
        stop();
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(STOP_WAIT_MILLIS);
        for (Thread thread : threads()) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return;
            }
            try {
                thread.join(Math.max(1, left / 1_000_000));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    /** 0 when every player did what it was started for, else 1. */
    public static int exitCode(List<PlayerReport> reports) {
        for (PlayerReport report : reports) {
            if (!report.outcome().ok()) {
                return 1;
            }
        }
        return reports.isEmpty() ? 1 : 0;
    }

    private List<LivePlayer> players() {
        synchronized (started) {
            return List.copyOf(started);
        }
    }

    private List<Thread> threads() {
        synchronized (started) {
            return List.copyOf(threads);
        }
    }
}
