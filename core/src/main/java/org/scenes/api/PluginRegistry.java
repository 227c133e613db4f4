package org.scenes.api;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.TreeMap;
import java.util.jar.JarFile;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Every metric, selector and transform provider visible to a class loader, discovered once
 * with {@link ServiceLoader} and looked up by short name, case-insensitively. A spec may
 * carry an argument after a colon ({@code script:metric.groovy}), handed to the provider.
 * Two providers of one kind with the same name are an error, not "first wins": with jars
 * from many sources, silently picking one would hide which code runs.
 */
public final class PluginRegistry {
    private static final Pattern NAME = Pattern.compile("[a-z0-9][a-z0-9-]*");
    /** Environment variable holding plugin directories, separated like PATH. */
    public static final String PLUGIN_PATH_VARIABLE = "SCENES_PLUGIN_PATH";

    private final Map<PluginKind, Map<String, NamedProvider>> providers = new EnumMap<>(PluginKind.class);
    private List<String> warnings = List.of();

    private PluginRegistry(ClassLoader loader) {
        for (PluginKind kind : PluginKind.values()) {
            Map<String, NamedProvider> byName = new TreeMap<>();
            try {
                for (NamedProvider provider : ServiceLoader.load(kind.service(), loader)) {
                    register(kind, byName, provider);
                }
            } catch (ServiceConfigurationError e) {
                throw new PluginException("a " + kind.label() + " plugin could not be loaded: " + e.getMessage(), e);
            }
            providers.put(kind, Collections.unmodifiableMap(byName));
        }
    }

    /**
     * The providers on the class path of core itself.
     *
     * @return the registry
     * @throws PluginException when a provider cannot be loaded or two share a name
     */
    public static PluginRegistry load() {
        return new PluginRegistry(PluginRegistry.class.getClassLoader());
    }

    /**
     * @param loader where to look for providers
     * @return the registry of every provider that loader sees
     * @throws PluginException when a provider cannot be loaded or two share a name
     */
    public static PluginRegistry load(ClassLoader loader) {
        return new PluginRegistry(loader);
    }

    /**
     * The providers on the class path plus those in every {@code .jar} of the given directories.
     *
     * @param pluginDirectories directories of plugin jars; none for the class path alone
     * @return the registry; jars skipped are in {@link #warnings()}
     * @throws PluginException when a directory is missing, a provider cannot be loaded or two share a name
     */
    public static PluginRegistry load(List<Path> pluginDirectories) {
        if (pluginDirectories.isEmpty()) {
            return load();
        }
        List<URL> jars = new ArrayList<>();
        List<String> warnings = new ArrayList<>();
        for (Path directory : pluginDirectories) {
            if (!Files.isDirectory(directory)) {
                throw new PluginException("plugin directory " + directory + " does not exist or is not a directory");
            }
            try (Stream<Path> files = Files.list(directory)) {
                for (Path jar : files.filter(f -> f.getFileName().toString().endsWith(".jar")).sorted().toList()) {
                    String problem = jarProblem(jar);
                    if (problem == null || !problem.startsWith("not")) {
                        // a jar without a plugin may be a library of the plugins beside it: kept
                        jars.add(jar.toUri().toURL());
                    }
                    if (problem != null) {
                        warnings.add(jar + ": " + problem);
                    }
                }
            } catch (MalformedURLException e) {
                throw new PluginException("bad plugin jar path in " + directory, e);
            } catch (IOException e) {
                throw new PluginException("cannot list plugin directory " + directory + ": " + e.getMessage(), e);
            }
        }
        PluginRegistry registry = new PluginRegistry(new URLClassLoader(jars.toArray(URL[]::new),
                PluginRegistry.class.getClassLoader()));
        registry.warnings = List.copyOf(warnings);
        return registry;
    }

    /** Why a jar on the plugin path cannot add a plugin (not a zip, no service entry), or null when it can. */
    private static String jarProblem(Path jar) {
        try (JarFile file = new JarFile(jar.toFile())) {
            for (PluginKind kind : PluginKind.values()) {
                if (file.getEntry("META-INF/services/" + kind.service().getName()) != null) {
                    return null;
                }
            }
            return "holds no scenes plugin (no META-INF/services entry of a scenes plugin kind);"
                    + " kept on the class path as a library";
        } catch (IOException e) {
            return "not a readable jar (" + (e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage())
                    + "); ignored";
        }
    }

    /** @return jars on the plugin path that were skipped, one line each, for the command line to print once */
    public List<String> warnings() {
        return warnings;
    }

    /**
     * @param text directories as {@value #PLUGIN_PATH_VARIABLE} holds them, separated by the platform's path separator
     * @return the directories, none for null or blank text
     */
    public static List<Path> parsePluginPath(String text) {
        if (text == null || text.isBlank()) {
            return List.of();
        }
        return Stream.of(text.split(java.io.File.pathSeparator)).filter(s -> !s.isBlank()).map(Path::of).toList();
    }

    private static void register(PluginKind kind, Map<String, NamedProvider> byName, NamedProvider provider) {
        String name = provider.name();
        if (name == null || !NAME.matcher(name).matches()) {
            throw new PluginException("the " + kind.label() + " plugin " + provider.getClass().getName() + " from "
                    + origin(provider) + " has an invalid name '" + name
                    + "': use lower case letters, digits and dashes, starting with a letter or digit");
        }
        for (TuneDimension dimension : provider.tuneDimensions()) {
            if (!provider.options().containsKey(dimension.option())) {
                throw new PluginException("the " + kind.label() + " plugin '" + name + "' from " + origin(provider)
                        + " declares the tune dimension '" + dimension.option() + "', which is not one of its options");
            }
        }
        NamedProvider previous = byName.putIfAbsent(name, provider);
        if (previous != null) {
            throw new PluginException("two " + kind.label() + " plugins are named '" + name + "': "
                    + previous.getClass().getName() + " from " + origin(previous) + " and "
                    + provider.getClass().getName() + " from " + origin(provider) + "; remove one of the jars");
        }
    }

    /**
     * @param spec a metric's name, optionally followed by {@code :argument}
     * @param config the configuration; its options must be ones the metric lists
     * @return a new metric
     * @throws PluginException for an unknown name or option, or a configuration the metric refuses
     */
    public SceneMetric metric(String spec, PluginConfig config) {
        MetricProvider provider = provider(MetricProvider.class, spec);
        return provider.create(configure(PluginKind.METRIC, provider, spec, config));
    }

    /**
     * @param spec a selector's name, optionally followed by {@code :argument}
     * @param config the configuration; its options must be ones the selector lists
     * @return a new selector
     * @throws PluginException for an unknown name or option, or a configuration the selector refuses
     */
    public ActionSelector selector(String spec, PluginConfig config) {
        SelectorProvider provider = provider(SelectorProvider.class, spec);
        return provider.create(configure(PluginKind.SELECTOR, provider, spec, config));
    }

    /**
     * @param spec a transform's name, optionally followed by {@code :argument}
     * @param config the configuration; its options must be ones the transform lists
     * @return a new transform, for one sequence of scenes
     * @throws PluginException for an unknown name or option, or a configuration the transform refuses
     */
    public SceneTransform transform(String spec, PluginConfig config) {
        TransformProvider provider = provider(TransformProvider.class, spec);
        return provider.create(configure(PluginKind.TRANSFORM, provider, spec, config));
    }

    /**
     * The provider of one service interface that a spec names, typed: no cast at the caller.
     *
     * @param <P> the service interface
     * @param service {@link MetricProvider}, {@link SelectorProvider} or {@link TransformProvider}
     * @param spec the provider's name, optionally followed by {@code :argument}
     * @return the provider
     * @throws PluginException when no provider of that kind has the name
     */
    public <P extends NamedProvider> P provider(Class<P> service, String spec) {
        return service.cast(find(PluginKind.of(service), spec));
    }

    /**
     * The provider a spec names; fails with the list of available names.
     *
     * @param kind metric, selector or transform
     * @param spec the provider's name, optionally followed by {@code :argument}
     * @return the provider
     * @throws PluginException when no provider of that kind has the name
     */
    public NamedProvider find(PluginKind kind, String spec) {
        String name = nameOf(spec);
        NamedProvider provider = providers.get(kind).get(name);
        if (provider == null) {
            throw new PluginException("no " + kind.label() + " named '" + name + "'. Available " + kind.label() + "s: "
                    + String.join(", ", names(kind)) + ". A " + kind.label() + " from another jar needs that jar in a "
                    + "plugin directory (" + PLUGIN_PATH_VARIABLE + ").");
        }
        return provider;
    }

    /**
     * Checks the spec's provider exists and accepts the config's options, without creating anything.
     *
     * @param kind metric, selector or transform
     * @param spec the provider's name, optionally followed by {@code :argument}
     * @param config the configuration to check
     * @throws PluginException for an unknown name or option
     */
    public void check(PluginKind kind, String spec, PluginConfig config) {
        configure(kind, find(kind, spec), spec, config);
    }

    private static PluginConfig configure(PluginKind kind, NamedProvider provider, String spec, PluginConfig config) {
        for (String option : config.options().keySet()) {
            if (!provider.options().containsKey(option)) {
                throw new PluginException("the " + kind.label() + " '" + provider.name() + "' has no option '" + option
                        + "'" + (provider.options().isEmpty() ? "; it takes no options"
                        : "; its options: " + String.join(", ", new TreeMap<>(provider.options()).keySet())));
            }
        }
        int colon = spec.indexOf(':');
        return config.withArgument(colon < 0 ? "" : spec.substring(colon + 1));
    }

    private static String nameOf(String spec) {
        if (spec == null || spec.isBlank()) {
            throw new PluginException("a plugin name is required");
        }
        int colon = spec.indexOf(':');
        return (colon < 0 ? spec : spec.substring(0, colon)).trim().toLowerCase(Locale.ROOT);
    }

    /**
     * The dimensions {@code scenes tune} may search for a provider, by option key.
     *
     * @param kind metric, selector or transform
     * @param spec the provider's name, optionally followed by {@code :argument}
     * @return the provider's declared dimensions, in its order
     * @throws PluginException when no provider of that kind has the name
     */
    public Map<String, TuneDimension> tuneDimensions(PluginKind kind, String spec) {
        Map<String, TuneDimension> dimensions = new LinkedHashMap<>();
        for (TuneDimension dimension : find(kind, spec).tuneDimensions()) {
            dimensions.put(dimension.option(), dimension);
        }
        return dimensions;
    }

    /**
     * @param kind metric, selector or transform
     * @return the names of that kind's providers, sorted
     */
    public List<String> names(PluginKind kind) {
        return List.copyOf(providers.get(kind).keySet());
    }

    /** @return every provider of every kind, sorted by kind then name */
    public List<PluginInfo> list() {
        List<PluginInfo> infos = new ArrayList<>();
        for (PluginKind kind : PluginKind.values()) {
            for (NamedProvider provider : providers.get(kind).values()) {
                infos.add(new PluginInfo(kind, provider.name(), provider.description(), origin(provider),
                        new TreeMap<>(provider.options())));
            }
        }
        return infos;
    }

    static String origin(NamedProvider provider) {
        CodeSource source = provider.getClass().getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return "(unknown origin)";
        }
        try {
            return Path.of(source.getLocation().toURI()).getFileName().toString();
        } catch (Exception e) {
            return source.getLocation().toString();
        }
    }
}
