package org.scenes.cli;

import java.util.List;
import java.util.concurrent.CountDownLatch;

/**
 * How the long-running commands that keep logs, {@code scenes server} and {@code scenes proxy},
 * are stopped. Ctrl-C (SIGINT) and SIGTERM are their documented way to stop, not a failure:
 * both are handled by running {@code stop} on a thread of its own, and the command completes its
 * logs and returns its own exit status, 0 after a clean shutdown (the JVM's default would end at
 * once with 130 or 143). A shutdown hook covers the other ways the JVM ends: it runs
 * {@code stop} too and waits for {@code done}, so the logs are complete before the JVM is gone.
 * A signal ignored when the JVM started (a background job of a non-interactive shell ignores
 * SIGINT) stays ignored, as for any program.
 */
final class StopSignals implements AutoCloseable {
    private final Thread hook;

    private StopSignals(Thread hook) {
        this.hook = hook;
    }

    /**
     * Installs the handlers; {@code stop} may be called more than once and from several threads,
     * {@code done} is counted down once the command's shutdown is complete.
     */
    static StopSignals install(String name, Runnable stop, CountDownLatch done) {
        for (String signal : List.of("INT", "TERM")) {
            try {
                sun.misc.Signal.handle(new sun.misc.Signal(signal), s -> new Thread(stop, name + "-stop").start());
            } catch (IllegalArgumentException unavailable) {
                // no such signal here: the shutdown hook still completes the logs
            }
        }
        Thread hook = new Thread(() -> {
            stop.run();
            try {
                done.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, name + "-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        return new StopSignals(hook);
    }

    /** The command ended by itself: its shutdown hook is not needed any more. */
    @Override
    public void close() {
        ShutdownHooks.remove(hook); // unless it is running: then it waits for the shutdown to complete
    }
}
