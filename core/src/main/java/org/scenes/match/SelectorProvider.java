package org.scenes.match;

import org.scenes.plugin.NamedProvider;
import org.scenes.plugin.PluginConfig;

/** Service found with {@link java.util.ServiceLoader} that makes a named {@link ActionSelector}. */
public interface SelectorProvider extends NamedProvider {
    ActionSelector create(PluginConfig config);
}
