package org.scenes.plugins.script;

import org.scenes.api.MetricProvider;
import org.scenes.api.PluginConfig;
import org.scenes.api.SceneMetric;

/** {@code script:path/to/metric.groovy}: a metric written as a Groovy script (docs/scripting.md). */
public final class ScriptMetricProvider implements MetricProvider {
    @Override
    public String name() {
        return "script";
    }

    @Override
    public String description() {
        return "Groovy metric script, statically compiled: script:path/to/metric.groovy (docs/scripting.md)";
    }

    @Override
    public SceneMetric create(PluginConfig config) {
        String path = config.argument();
        MetricScript script = Scripts.instantiate("metric", path, MetricScript.class);
        script.configure(config);
        Scripts.setUp("metric", path, script);
        return ScriptedMetric.of(script, path, Scripts.fileName(path));
    }
}
