package org.scenes.script;

import org.scenes.match.SceneMetric;
import org.scenes.scene.Scene;

/** A metric script instance, with exceptions it throws located in the script. */
final class ScriptedMetric implements SceneMetric {
    private final MetricScript script;
    private final String path;
    private final String fileName;

    ScriptedMetric(MetricScript script, String path, String fileName) {
        this.script = script;
        this.path = path;
        this.fileName = fileName;
    }

    @Override
    public double distance(Scene query, Scene stored) {
        try {
            return script.distance(query, stored);
        } catch (RuntimeException | StackOverflowError | AssertionError e) {
            throw ScriptFailure.of(path, fileName, "comparing the query scene of cycle " + query.cycle()
                    + " with the stored scene of cycle " + stored.cycle(), e);
        }
    }

    @Override
    public boolean isTrueMetric() {
        return script.isTrueMetric();
    }

    @Override
    public String toString() {
        return "script:" + path;
    }
}
