package org.scenes.spark;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;

/**
 * What an executor keeps between the tasks of one job: the decoded scene files, each fold's scenes
 * through the configuration's transforms, and each fold's knowledge base, built by the first task
 * that needs it and then shared (read-only) by every task of that fold on this executor. One job's
 * state is kept at a time: a new job replaces it.
 */
final class ExecutorState {
    private static final Object LOCK = new Object();
    private static String currentJob;
    private static ExecutorState current;
    private static final Map<List<String>, PluginRegistry> REGISTRIES = new ConcurrentHashMap<>();

    /** A fold's scenes: the test sequence and the knowledge base of the others (or the next). */
    record Fold(List<Scene> test, KnowledgeBase train) {
    }

    private final List<SceneFile> files;
    private final Map<String, Folds.Sequences> sequences = new ConcurrentHashMap<>();
    private final Map<String, Fold> folds = new ConcurrentHashMap<>();

    private ExecutorState(List<SceneFile> files) {
        this.files = files;
    }

    /** This executor's state for a job, decoding the job's files the first time. */
    static ExecutorState forJob(String job, Supplier<SceneData> data) {
        synchronized (LOCK) {
            if (!job.equals(currentJob)) {
                current = null; // the previous job's scenes go before this one's are decoded
                current = new ExecutorState(data.get().decode());
                currentJob = job;
            }
            return current;
        }
    }

    /** The registry over the class path and these plugin directories, loaded once per executor. */
    static PluginRegistry registry(List<String> pluginPath) {
        return REGISTRIES.computeIfAbsent(List.copyOf(pluginPath),
                path -> PluginRegistry.load(path.stream().map(Path::of).toList()));
    }

    Fold fold(MatchConfig config, PluginRegistry registry, int fold, Folds.Protocol protocol) {
        String key = ConfigSpec.transformKey(config);
        return folds.computeIfAbsent(key + "#" + fold, k -> {
            Folds.Sequences transformed = sequences.computeIfAbsent(key, t -> Folds.sequences(files, config, registry));
            return new Fold(transformed.test(fold), KnowledgeBase.of(files.get(0).grid(),
                    transformed.training(fold, protocol)));
        });
    }

    /** Knowledge bases built on this executor so far in the current job (for the tests). */
    static int knowledgeBases() {
        synchronized (LOCK) {
            return current == null ? 0 : current.folds.size();
        }
    }
}
