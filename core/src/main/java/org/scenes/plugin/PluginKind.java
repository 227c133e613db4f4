package org.scenes.plugin;

import org.scenes.match.MetricProvider;
import org.scenes.match.SelectorProvider;
import org.scenes.match.TransformProvider;

/** The three plugin families and the service interface each is loaded through. */
public enum PluginKind {
    METRIC("metric", MetricProvider.class),
    SELECTOR("selector", SelectorProvider.class),
    TRANSFORM("transform", TransformProvider.class);

    private final String label;
    private final Class<? extends NamedProvider> service;

    PluginKind(String label, Class<? extends NamedProvider> service) {
        this.label = label;
        this.service = service;
    }

    public String label() {
        return label;
    }

    public Class<? extends NamedProvider> service() {
        return service;
    }
}
