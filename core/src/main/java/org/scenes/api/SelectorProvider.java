package org.scenes.api;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link ActionSelector}. */
public interface SelectorProvider extends NamedProvider {
    /**
     * @param config weights, checked options, seed and argument
     * @return a new selector, used by one thread
     * @throws PluginException when the configuration cannot be used
     */
    ActionSelector create(PluginConfig config);
}
