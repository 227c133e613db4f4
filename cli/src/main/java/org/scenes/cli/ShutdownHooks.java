package org.scenes.cli;

/**
 * The shutdown hooks by which commands report what an interrupt left complete. A signal may come
 * while the command is still starting, when the JVM refuses new hooks: the report is made at once.
 */
final class ShutdownHooks {
    private ShutdownHooks() {
    }

    /** Adds {@code hook}; when the JVM is stopping already, runs it now and returns false. */
    static boolean addOrRun(Thread hook) {
        try {
            Runtime.getRuntime().addShutdownHook(hook);
            return true;
        } catch (IllegalStateException stopping) {
            hook.run();
            return false;
        }
    }

    /** Removes {@code hook} unless it is running (the JVM is stopping: it reports). */
    static void remove(Thread hook) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException stopping) {
            // the hook reports
        }
    }
}
