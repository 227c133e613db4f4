package org.scenes.cli;

/**
 * The commands' shutdown hooks (reports of what an interrupt left complete, players' goodbyes,
 * logs completed). A signal may come while a command is still starting, when the JVM refuses new
 * hooks: the hook's work is then done at once.
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

    /** Removes {@code hook} unless it is running (the JVM is stopping: it does its work). */
    static void remove(Thread hook) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException stopping) {
            // the hook is running
        }
    }
}
