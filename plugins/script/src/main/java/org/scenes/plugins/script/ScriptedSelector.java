package org.scenes.plugins.script;

import java.util.List;
import java.util.random.RandomGenerator;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.Neighbour;

/** A selector script instance, with exceptions it throws located in the script. */
final class ScriptedSelector implements ActionSelector {
    private final SelectorScript script;
    private final String path;
    private final String fileName;
    private final ScriptWatch watch = new ScriptWatch();

    ScriptedSelector(SelectorScript script, String path, String fileName) {
        this.script = script;
        this.path = path;
        this.fileName = fileName;
    }

    @Override
    public Action select(List<Neighbour> nearest, RandomGenerator random) {
        watch.enter();
        try {
            return script.select(nearest, random);
        } catch (RuntimeException | StackOverflowError | AssertionError e) {
            throw ScriptFailure.of(path, fileName, selecting(nearest), e);
        } catch (Exception e) { // checked, thrown through Groovy: the watchdog's interruption among them
            throw watch.failure(e, path, fileName, selecting(nearest));
        } finally {
            watch.exit();
        }
    }

    private static String selecting(List<Neighbour> nearest) {
        return "selecting among " + nearest.size() + " neighbours, the nearest being the stored scene of cycle "
                + nearest.get(0).scene().cycle();
    }

    @Override
    public String toString() {
        return "script:" + path;
    }
}
