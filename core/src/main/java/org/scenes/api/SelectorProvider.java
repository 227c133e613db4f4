package org.scenes.api;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link ActionSelector}. */
public interface SelectorProvider extends NamedProvider {
    ActionSelector create(PluginConfig config);
}
