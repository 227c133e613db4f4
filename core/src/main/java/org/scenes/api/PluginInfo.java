package org.scenes.api;

import java.util.Map;

/**
 * What {@code scenes plugins} lists about one provider.
 *
 * @param kind metric, selector or transform
 * @param name the short name users type
 * @param description one line
 * @param origin the jar or directory the provider was loaded from
 * @param options option name to description
 */
public record PluginInfo(PluginKind kind, String name, String description, String origin, Map<String, String> options) {
}
