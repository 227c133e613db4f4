package org.scenes.api;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link SceneTransform}. */
public interface TransformProvider extends NamedProvider {
    /** A fresh transform for one sequence of scenes. */
    SceneTransform create(PluginConfig config);
}
