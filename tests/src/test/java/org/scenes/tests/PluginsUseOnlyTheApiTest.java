package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The plugins (plugins/*, and the template in examples/metric-plugin) are written against the plugin
 * API, org.scenes.api, alone: no source names an org.scenes.internal package, and every service file
 * names an API interface. Compiling cannot check it, since the internal packages are public for the
 * project's own modules.
 */
class PluginsUseOnlyTheApiTest {
    private static final Path ROOT = Path.of(System.getProperty("scenes.root", ".."));
    private static final Pattern INTERNAL = Pattern.compile("org\\.scenes\\.internal(\\.[a-z]+)*");
    /**
     * The sweep language of the script module: it describes experiments for {@code scenes experiment
     * --script} (axes, folds), a command-line extension that lives beside the script plugins, not a
     * plugin; it may use the experiment classes.
     */
    private static final Set<String> SWEEP_LANGUAGE = Set.of(
            "plugins/script/src/main/java/org/scenes/plugins/script/SweepScript.java",
            "plugins/script/src/main/java/org/scenes/plugins/script/Sweeps.java");

    @Test
    void pluginSourcesNameNoInternalPackage() throws IOException {
        List<Path> sources = pluginFiles("java", "groovy");
        assertTrue(sources.size() > 30, "plugin sources not found under " + ROOT.toAbsolutePath() + ": " + sources);
        List<String> violations = new ArrayList<>();
        Set<String> exemptSeen = new TreeSet<>();
        for (Path source : sources) {
            String relative = ROOT.relativize(source).toString().replace('\\', '/');
            List<String> lines = Files.readAllLines(source);
            for (int i = 0; i < lines.size(); i++) {
                Matcher internal = INTERNAL.matcher(lines.get(i));
                while (internal.find()) {
                    if (SWEEP_LANGUAGE.contains(relative)) {
                        exemptSeen.add(relative);
                    } else {
                        violations.add(relative + ":" + (i + 1) + ": " + internal.group());
                    }
                }
            }
        }
        assertEquals(List.of(), violations, "plugins use org.scenes.api only; expose what they need there");
        // the exemption is no wider than what needs it
        assertEquals(new TreeSet<>(SWEEP_LANGUAGE), exemptSeen);
    }

    @Test
    void everyServiceFileNamesAnApiInterface() throws IOException {
        List<Path> services = new ArrayList<>();
        for (Path file : pluginFiles("")) {
            if (file.getParent().endsWith(Path.of("META-INF", "services"))) {
                services.add(file);
            }
        }
        assertTrue(services.size() >= 10, "service files not found: " + services);
        for (Path service : services) {
            String name = service.getFileName().toString();
            assertTrue(name.matches("org\\.scenes\\.api\\.(Metric|Selector|Transform)Provider"), service.toString());
        }
    }

    /** Files under plugins/&#42;/src/main and examples/metric-plugin/src/main ending in one of the extensions. */
    private static List<Path> pluginFiles(String... extensions) throws IOException {
        List<Path> roots = new ArrayList<>();
        try (Stream<Path> plugins = Files.list(ROOT.resolve("plugins"))) {
            plugins.map(p -> p.resolve("src/main")).filter(Files::isDirectory).forEach(roots::add);
        }
        roots.add(ROOT.resolve("examples/metric-plugin/src/main"));
        List<Path> files = new ArrayList<>();
        for (Path root : roots) {
            try (Stream<Path> walk = Files.walk(root)) {
                walk.filter(Files::isRegularFile)
                        .filter(f -> Stream.of(extensions).anyMatch(e -> f.toString().endsWith(e)))
                        .sorted().forEach(files::add);
            }
        }
        return files;
    }
}
