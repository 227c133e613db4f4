package org.scenes.plugins.script;

import org.scenes.api.EncodedMetric;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

/** A metric script instance, with exceptions it throws located in the script. */
class ScriptedMetric implements SceneMetric {
    final MetricScript script;
    final String path;
    final String fileName;
    final ScriptWatch watch = new ScriptWatch();

    ScriptedMetric(MetricScript script, String path, String fileName) {
        this.script = script;
        this.path = path;
        this.fileName = fileName;
    }

    /** The wrapper for a script: with the encoded fast path when the script defines it. */
    static SceneMetric of(MetricScript script, String path, String fileName) {
        return script.encodes() ? new Encoded(script, path, fileName) : new ScriptedMetric(script, path, fileName);
    }

    @Override
    public double distance(Scene query, Scene stored) {
        watch.enter();
        try {
            return script.distance(query, stored);
        } catch (RuntimeException | StackOverflowError | AssertionError e) {
            throw ScriptFailure.of(path, fileName, comparing(query, stored), e);
        } catch (Exception e) { // checked, thrown through Groovy: the watchdog's interruption among them
            throw watch.failure(e, path, fileName, comparing(query, stored));
        } finally {
            watch.exit();
        }
    }

    private static String comparing(Scene query, Scene stored) {
        return "comparing the query scene of cycle " + query.cycle() + " with the stored scene of cycle " + stored.cycle();
    }

    @Override
    public boolean isTrueMetric() {
        return script.isTrueMetric();
    }

    @Override
    public String toString() {
        return "script:" + path;
    }

    /** A script of the fast form: scenes are encoded once, distances computed between arrays. */
    static final class Encoded extends ScriptedMetric implements EncodedMetric<double[]> {
        Encoded(MetricScript script, String path, String fileName) {
            super(script, path, fileName);
        }

        @Override
        public double[] encode(Scene scene) {
            watch.enter();
            try {
                return script.encode(scene);
            } catch (RuntimeException | StackOverflowError | AssertionError e) {
                throw ScriptFailure.of(path, fileName, "encoding the scene of cycle " + scene.cycle(), e);
            } catch (Exception e) {
                throw watch.failure(e, path, fileName, "encoding the scene of cycle " + scene.cycle());
            } finally {
                watch.exit();
            }
        }

        @Override
        public double distance(double[] query, double[] stored, double bound) {
            watch.enter();
            try {
                return script.distance(query, stored, bound);
            } catch (RuntimeException | StackOverflowError | AssertionError e) {
                throw ScriptFailure.of(path, fileName, "comparing two encoded scenes", e);
            } catch (Exception e) {
                throw watch.failure(e, path, fileName, "comparing two encoded scenes");
            } finally {
                watch.exit();
            }
        }

        @Override
        public double distance(Scene query, Scene stored) {
            return distance(encode(query), encode(stored), Double.POSITIVE_INFINITY);
        }
    }
}
