package org.scenes.api;

/** The three plugin families and the service interface each is loaded through. */
public enum PluginKind {
    /** Metrics, loaded through {@link MetricProvider}. */
    METRIC("metric", MetricProvider.class),
    /** Action selectors, loaded through {@link SelectorProvider}. */
    SELECTOR("selector", SelectorProvider.class),
    /** Scene transforms, loaded through {@link TransformProvider}. */
    TRANSFORM("transform", TransformProvider.class);

    private final String label;
    private final Class<? extends NamedProvider> service;

    PluginKind(String label, Class<? extends NamedProvider> service) {
        this.label = label;
        this.service = service;
    }

    /** @return the kind's name in messages: metric, selector or transform */
    public String label() {
        return label;
    }

    /** @return the service interface providers of this kind implement */
    public Class<? extends NamedProvider> service() {
        return service;
    }

    /**
     * @param service one of the three service interfaces
     * @return the kind loaded through it
     */
    public static PluginKind of(Class<? extends NamedProvider> service) {
        for (PluginKind kind : values()) {
            if (kind.service == service) {
                return kind;
            }
        }
        throw new IllegalArgumentException(service.getName() + " is not a plugin service interface");
    }
}
