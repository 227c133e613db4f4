package org.scenes.tests.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * The thread CPU time of each operation of one benchmark iteration, summarised as its p50 and
 * p99: on a loaded machine wall-clock samples mostly measure the waits for a core, CPU time does not.
 */
final class CpuTimes {
    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    private long[] nanos = new long[1 << 16];
    private int count;

    /** Forgets the times taken so far (at the start of an iteration). */
    void reset() {
        count = 0;
    }

    /** Runs the operation, taking its thread CPU time. */
    <T> T time(Supplier<T> operation) {
        long start = threads.getCurrentThreadCpuTime();
        T result = operation.get();
        if (count == nanos.length) {
            nanos = Arrays.copyOf(nanos, count * 2);
        }
        nanos[count++] = threads.getCurrentThreadCpuTime() - start;
        return result;
    }

    /** "N decisions, CPU us p50 X p99 Y", or null when none was timed (the iteration ran another benchmark). */
    String summary() {
        if (count == 0) {
            return null;
        }
        long[] sorted = Arrays.copyOf(nanos, count);
        Arrays.sort(sorted);
        return String.format(Locale.ROOT, "%d decisions, CPU us p50 %.1f p99 %.1f", count,
                sorted[(count - 1) / 2] / 1e3, sorted[(int) Math.ceil(0.99 * count) - 1] / 1e3);
    }
}
