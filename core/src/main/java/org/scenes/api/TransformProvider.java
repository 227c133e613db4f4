package org.scenes.api;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link SceneTransform}. */
public interface TransformProvider extends NamedProvider {
    /**
     * A fresh transform for one sequence of scenes.
     *
     * @param config weights, checked options, seed and argument
     * @return a new transform, without state from earlier sequences
     * @throws PluginException when the configuration cannot be used
     */
    SceneTransform create(PluginConfig config);
}
