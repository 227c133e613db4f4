package org.scenes.plugins.script;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;

/**
 * Ends a script call that runs too long (a {@code while (true) {}} would otherwise hang the whole
 * command): scripts are compiled with Groovy's {@code ThreadInterrupt}, which checks the thread's
 * interrupt flag at every loop and method start, and one daemon thread interrupts a call that has
 * not returned within {@link #limit()}. A call costs two ordered stores of a counter, no clock
 * reading: the watchdog sees a call as stuck when the same odd count stays for the limit.
 */
final class ScriptWatch {
    /** From {@code -Dscenes.script.timeout.ms} (in {@code SCENES_OPTS}); one call of a script never needs seconds. */
    private static volatile Duration limit = Duration.ofMillis(Long.getLong("scenes.script.timeout.ms", 10_000));
    private static final Map<ScriptWatch, Boolean> WATCHED = Collections.synchronizedMap(new WeakHashMap<>());
    private static final VarHandle CALLS;
    private static Thread watchdog;

    static {
        try {
            CALLS = MethodHandles.lookup().findVarHandle(ScriptWatch.class, "calls", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    /** Calls started plus calls ended: odd while a call runs. Written by the calling thread only. */
    private long calls;
    private volatile Thread owner;
    private volatile boolean timedOut;
    /** The watchdog's own: the odd count it last saw and since when (nanoseconds). */
    private long seen = -1;
    private long seenSince;

    ScriptWatch() {
        WATCHED.put(this, Boolean.TRUE);
        startWatchdog();
    }

    static Duration limit() {
        return limit;
    }

    /** For tests: a short limit. */
    static void limit(Duration newLimit) {
        limit = newLimit;
    }

    void enter() {
        Thread current = Thread.currentThread();
        if (owner != current) {
            owner = current;
        }
        CALLS.setRelease(this, calls + 1);
    }

    void exit() {
        CALLS.setRelease(this, calls + 1);
    }

    /**
     * The failure for an exception a script call threw that is not a runtime exception: the
     * interruption of a call over the limit, named so, or another checked exception Groovy let through.
     */
    ScriptFailure failure(Exception e, String path, String fileName, String context) {
        if (e instanceof InterruptedException) {
            Thread.interrupted(); // the flag was for the script; the caller's thread goes on
            if (timedOut) {
                timedOut = false;
                InterruptedException over = new InterruptedException("a call ran longer than " + limit.toMillis()
                        + " ms (an endless loop?); -Dscenes.script.timeout.ms in SCENES_OPTS sets the limit");
                over.setStackTrace(e.getStackTrace()); // where the script was: its line
                return ScriptFailure.of(path, fileName, context, over);
            }
        }
        return ScriptFailure.of(path, fileName, context, e);
    }

    private static synchronized void startWatchdog() {
        if (watchdog != null) {
            return;
        }
        watchdog = new Thread(ScriptWatch::watch, "scenes-script-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
    }

    private static void watch() {
        while (true) {
            long every = Math.max(10, limit.toMillis() / 10);
            try {
                Thread.sleep(every);
            } catch (InterruptedException e) {
                return;
            }
            List<ScriptWatch> watches;
            synchronized (WATCHED) {
                watches = new ArrayList<>(WATCHED.keySet());
            }
            long now = System.nanoTime();
            for (ScriptWatch watch : watches) {
                watch.check(now);
            }
        }
    }

    private void check(long now) {
        long count = (long) CALLS.getAcquire(this);
        if ((count & 1) == 0) {
            seen = -1;
            return;
        }
        if (count != seen) {
            seen = count;
            seenSince = now;
        } else if (now - seenSince >= limit.toNanos()) {
            timedOut = true;
            Thread running = owner;
            if (running != null) {
                running.interrupt();
            }
            seenSince = now; // once per limit, not at every look
        }
    }
}
