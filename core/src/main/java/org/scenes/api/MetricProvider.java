package org.scenes.api;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link SceneMetric}. */
public interface MetricProvider extends NamedProvider {
    /**
     * @param config weights, checked options, seed and argument
     * @return a new metric, used by one thread
     * @throws PluginException when the configuration cannot be used
     */
    SceneMetric create(PluginConfig config);
}
