package org.scenes.api;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link SceneMetric}. */
public interface MetricProvider extends NamedProvider {
    SceneMetric create(PluginConfig config);
}
