package org.scenes.internal.convert;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** The workers of one conversion: the players dealt out in turn, every step handed to each. */
final class RebuildWorkers {
    private final List<RebuildWorker> workers = new ArrayList<>();
    private int next;

    RebuildWorkers(RebuildSettings settings, Path gameLog, GameParameters parameters, PlayerSlots slots) {
        int threads = settings.threads();
        for (int i = 0; i < threads; i++) {
            PerceptWriter percepts = new PerceptWriter(gameLog, parameters, settings.sceneConverter());
            RebuildWorker worker = new RebuildWorker(percepts, parameters, slots, settings.commandsBeforeSee(),
                    threads > 1);
            if (threads > 1) {
                worker.start("rebuild-" + i);
            }
            workers.add(worker);
        }
    }

    /** The worker of the next new player. */
    RebuildWorker next() {
        return workers.get(next++ % workers.size());
    }

    void submit(RebuildStep step) throws IOException {
        for (RebuildWorker worker : workers) {
            worker.submit(step);
        }
    }

    /** Ends the workers' threads (once), rethrowing the first failure. */
    void stop() throws IOException {
        for (RebuildWorker worker : workers) {
            worker.stop();
        }
        for (RebuildWorker worker : workers) {
            worker.rethrow();
        }
    }
}
