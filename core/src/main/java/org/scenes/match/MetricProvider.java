package org.scenes.match;

import org.scenes.plugin.NamedProvider;
import org.scenes.plugin.PluginConfig;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link SceneMetric}. */
public interface MetricProvider extends NamedProvider {
    SceneMetric create(PluginConfig config);
}
