package org.scenes.internal.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * Runs every configuration of a sweep, several at a time. Each configuration is validated on
 * its own with the sweep's seed, and results are gathered in sweep order, so the numbers do
 * not depend on the number of threads or on which configuration finished first.
 */
public final class Experiment {
    /**
     * Validates one configuration. It is called from several threads at once and must share no
     * mutable state between calls: what it returns may depend on its argument only.
     */
    public interface Validation {
        Map<String, Double> validate(Configuration configuration);
    }

    private Experiment() {
    }

    /**
     * @param threads how many configurations run at once
     * @param done called after each configuration, from the thread that ran it (for progress)
     */
    public static ResultTable run(Sweep sweep, Validation validation, int threads, Runnable done) {
        List<Configuration> configurations = sweep.configurations();
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Math.min(threads, configurations.size())), runnable -> {
            Thread thread = new Thread(runnable, "sweep");
            thread.setDaemon(true);
            return thread;
        });
        try {
            List<Future<Result>> futures = new ArrayList<>();
            for (Configuration configuration : configurations) {
                futures.add(pool.submit(() -> {
                    Result result = new Result(configuration, validation.validate(configuration));
                    done.run();
                    return result;
                }));
            }
            List<Result> results = new ArrayList<>();
            for (int i = 0; i < futures.size(); i++) {
                results.add(await(futures.get(i), configurations.get(i)));
            }
            return new ResultTable(sweep, results);
        } finally {
            pool.shutdownNow();
        }
    }

    private static Result await(Future<Result> future, Configuration configuration) {
        try {
            return future.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("sweep interrupted", e);
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            String message = "configuration " + describe(configuration) + ": " + cause.getMessage();
            if (cause instanceof RuntimeException runtime && runtime.getClass() == IllegalArgumentException.class) {
                throw new IllegalArgumentException(message, cause);
            }
            throw new ExperimentException(message, cause);
        }
    }

    /** "metric=cell weights=1/1/1/1/0/1/1/1 k=3 selector=vote action-weights=1/1/1/1/1/1/1/1" */
    public static String describe(Configuration configuration) {
        StringBuilder text = new StringBuilder();
        for (Axis axis : Axis.values()) {
            text.append(text.length() == 0 ? "" : " ").append(axis.key()).append('=').append(configuration.value(axis));
        }
        return text.toString();
    }
}
