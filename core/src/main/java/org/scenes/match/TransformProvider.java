package org.scenes.match;

import org.scenes.plugin.NamedProvider;
import org.scenes.plugin.PluginConfig;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link SceneTransform}. */
public interface TransformProvider extends NamedProvider {
    /** A fresh transform for one sequence of scenes. */
    SceneTransform create(PluginConfig config);
}
