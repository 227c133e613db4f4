package org.scenes.plugins.script;

import org.scenes.api.ActionSelector;
import org.scenes.api.PluginConfig;
import org.scenes.api.SelectorProvider;

/** {@code script:path/to/selector.groovy}: a selector written as a Groovy script (docs/scripting.md). */
public final class ScriptSelectorProvider implements SelectorProvider {
    @Override
    public String name() {
        return "script";
    }

    @Override
    public String description() {
        return "Groovy selector script, statically compiled: script:path/to/selector.groovy (docs/scripting.md)";
    }

    @Override
    public ActionSelector create(PluginConfig config) {
        String path = config.argument();
        SelectorScript script = Scripts.instantiate("selector", path, SelectorScript.class);
        script.configure(config);
        Scripts.setUp("selector", path, script);
        return new ScriptedSelector(script, path, Scripts.fileName(path));
    }
}
