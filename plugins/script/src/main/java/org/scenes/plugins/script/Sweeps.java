package org.scenes.plugins.script;

import org.scenes.api.PluginException;
import org.scenes.internal.experiment.Sweep;

/** Reading sweep scripts: {@code scenes experiment SWEEP.groovy}. */
public final class Sweeps {
    private Sweeps() {
    }

    /**
     * Compiles and runs a sweep script and returns the sweep it describes.
     *
     * @param path the script's path as the user wrote it (messages name it)
     * @throws PluginException when the script is missing or does not compile
     * @throws ScriptFailure when the script throws; PluginException when it describes an impossible sweep
     */
    public static Sweep load(String path) {
        SweepScript script = Scripts.instantiate("sweep", path, SweepScript.class);
        Scripts.setUp("sweep", path, script);
        try {
            return script.sweep();
        } catch (IllegalArgumentException e) {
            throw new PluginException("the sweep " + path + " is incomplete: " + e.getMessage(), e);
        }
    }
}
