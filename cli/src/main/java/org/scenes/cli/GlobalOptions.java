package org.scenes.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.scenes.api.PluginRegistry;
import picocli.CommandLine.Option;
import picocli.CommandLine.ScopeType;

/** Options every subcommand accepts. */
final class GlobalOptions {
    @Option(names = "--verbose", scope = ScopeType.INHERIT, description = "Print stack traces of errors.")
    boolean verbose;

    @Option(names = "--plugin-path", scope = ScopeType.INHERIT, paramLabel = "DIR",
            description = "Directory of plugin jars to load (repeatable; also ${sys:line.separator}"
                    + "  the " + PluginRegistry.PLUGIN_PATH_VARIABLE + " environment variable).")
    List<Path> pluginPath = new ArrayList<>();

    private PluginRegistry registry;

    /** The registry over the class path, --plugin-path and the environment variable; built once. */
    PluginRegistry registry() {
        if (registry == null) {
            List<Path> directories = new ArrayList<>(pluginPath);
            directories.addAll(PluginRegistry.parsePluginPath(System.getenv(PluginRegistry.PLUGIN_PATH_VARIABLE)));
            registry = PluginRegistry.load(directories);
            for (String warning : registry.warnings()) {
                System.err.println("scenes: warning: " + warning);
            }
        }
        return registry;
    }
}
