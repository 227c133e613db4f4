package org.scenes.evaluate;

import java.util.function.Consumer;
import java.util.function.LongSupplier;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/**
 * The classic Krislet client's think loop in wall time: after each decision the brain rests
 * {@code millis} milliseconds, then decides on the first see taken after that decision (at once
 * when one came during the rest; should none come within a further {@link #GRACE_MILLIS}, at the
 * next message on the latest it has). {@link PacedBrain} counts server steps instead, so its
 * imitators decide in exactly every second step, where the client's 200 ms against rcssserver's
 * 105-113 ms steps gives 51-53 %. For real-time servers only: in process and on a synchronous
 * server the steps do not follow the clock. The policy is the brain's; only the tempo is the
 * teacher's.
 */
public final class ClockPacedBrain implements Brain {
    /** How long past its rest the brain waits for a see taken after its last decision. */
    static final long GRACE_MILLIS = 100;

    private final Brain inner;
    private final long restNanos;
    private final LongSupplier clock;
    private String latestSee;
    /** Whether the latest see came after the last decision. */
    private boolean fresh;
    private long decidedAt;
    private boolean decided;

    ClockPacedBrain(Brain inner, long millis, LongSupplier clock) {
        if (millis < 1) {
            throw new IllegalArgumentException("think milliseconds must be 1 or more, not " + millis);
        }
        this.inner = inner;
        this.restNanos = millis * 1_000_000L;
        this.clock = clock;
    }

    /** The brains of {@code factory} paced to one decision per {@code millis} ms of wall time; 0 leaves them as they are. */
    public static BrainFactory pace(BrainFactory factory, long millis) {
        if (millis < 0) {
            throw new IllegalArgumentException("think milliseconds must be 0 or more, not " + millis);
        }
        if (millis == 0) {
            return factory;
        }
        return new BrainFactory() {
            @Override
            public Brain create(String team, java.util.Random random) {
                return new ClockPacedBrain(factory.create(team, random), millis, System::nanoTime);
            }

            @Override
            public boolean goalie(int unum) {
                return factory.goalie(unum);
            }
        };
    }

    @Override
    public boolean repeatsKickOffMove() {
        return inner.repeatsKickOffMove();
    }

    @Override
    public java.util.Map<String, Long> counters() {
        return inner.counters();
    }

    @Override
    public void receive(String message, Consumer<String> send) {
        if (message.startsWith("(see ")) {
            latestSee = message;
            fresh = true;
        } else {
            inner.receive(message, send);
        }
        if (latestSee == null) {
            return;
        }
        long rested = decided ? clock.getAsLong() - decidedAt : Long.MAX_VALUE;
        if (rested >= restNanos && (fresh || rested >= restNanos + GRACE_MILLIS * 1_000_000L)) {
            decided = true;
            decidedAt = clock.getAsLong();
            fresh = false;
            inner.receive(latestSee, send);
        }
    }
}
