package org.scenes.cli;

import java.nio.file.Path;
import org.scenes.internal.files.Inputs;

/** Bounds of options that size work, and the one line for running out of memory. */
final class Limits {
    /** More threads than this only add contention on any machine scenes runs on. */
    static final int MAX_THREADS = 256;

    private Limits() {
    }

    /** A thread count option: 1 to {@link #MAX_THREADS}, else a usage error naming the option. */
    static int threads(String option, int threads) {
        if (threads < 1 || threads > MAX_THREADS) {
            throw new UsageException(option + " must be from 1 to " + MAX_THREADS + ", not " + threads);
        }
        return threads;
    }

    /**
     * Heap a stored scene of real size takes with both packed indexes: 377 MB per 10^6 scenes
     * measured (docs/performance.md, `gradle :tests:memoryBench`), rounded up.
     */
    static final long BYTES_PER_SCENE = 400;

    /** Refuses, before allocating, a count whose estimated heap exceeds this JVM's. */
    static void heapFor(String option, long count, long bytesEach) {
        long needMb = count * bytesEach >> 20;
        long heapMb = Runtime.getRuntime().maxMemory() >> 20;
        if (needMb > heapMb) {
            throw new UsageException(option + " " + count + " needs about " + needMb + " MB of heap and this JVM has "
                    + heapMb + " MB: give a smaller count, or more heap with SCENES_OPTS=-Xmx" + ((needMb >> 10) + 1) + "g");
        }
    }

    /** The OutOfMemoryError in {@code e} or its causes, or null. */
    static OutOfMemoryError outOfMemory(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof OutOfMemoryError error) {
                return error;
            }
        }
        return null;
    }

    /** One line for an exhausted heap: the heap's size, the input read last, how to give more. */
    static String outOfMemoryMessage() {
        long heapMb = Runtime.getRuntime().maxMemory() >> 20;
        Path input = Inputs.lastOpened();
        return "out of memory (Java heap of " + heapMb + " MB)" + (input == null ? "" : " after opening " + input)
                + ": give Java more with SCENES_OPTS=-Xmx" + Math.max(1, 2 * heapMb >> 10) + "g (or JAVA_OPTS), or use fewer"
                + " or smaller inputs";
    }
}
