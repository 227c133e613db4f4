package org.scenes.app;

/**
 * How a service reports long work: it begins with the number of steps, steps (from any thread),
 * and ends, also when it fails. A front end draws a bar, logs, or does nothing ({@link #NONE}).
 */
public interface Progress {
    /** Reports nothing. */
    Progress NONE = new Progress() {
        @Override
        public void begin(String task, long total) {
        }

        @Override
        public void step() {
        }

        @Override
        public void end() {
        }
    };

    /**
     * Work of {@code total} steps begins.
     *
     * @param task what is done, one word: {@code Validating}
     * @param total the steps to come
     */
    void begin(String task, long total);

    /** One step is done; called from any thread. */
    void step();

    /** {@code steps} steps are done (bytes of a log read); called from any thread. */
    default void stepBy(long steps) {
        for (long i = 0; i < steps; i++) {
            step();
        }
    }

    /** A new estimate of the total steps, for work whose size shows only as it is done. */
    default void total(long total) {
    }

    /** The work is over, done or failed. */
    void end();
}
