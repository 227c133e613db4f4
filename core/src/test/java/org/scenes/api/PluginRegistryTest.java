package org.scenes.api;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PluginRegistryTest {
    private final PluginRegistry registry = PluginRegistry.load();
    private final Scene empty = new Scene(0, null, List.of(), List.of());

    @Test
    void findsProvidersByNameIgnoringCase() {
        SceneMetric metric = registry.metric("COUNTING", PluginConfig.DEFAULT);
        assertEquals(0.0, metric.distance(empty, empty));
    }

    @Test
    void passesOptionsAndTheArgumentAfterTheColon() {
        SceneMetric scaled = registry.metric("constant:2.5", PluginConfig.DEFAULT);
        assertEquals(2.5, scaled.distance(empty, empty));
        PluginConfig config = PluginConfig.DEFAULT.withOptions(Map.of("scale", "3"));
        SeenObject ball = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 1, 0, Grid.DEFAULT);
        Scene two = new Scene(0, null, List.of(ball, ball), List.of());
        assertEquals(6.0, registry.metric("counting", config).distance(empty, two));
    }

    @Test
    void anUnknownNameListsTheAvailableOnes() {
        PluginException error = assertThrows(PluginException.class, () -> registry.metric("nosuch", PluginConfig.DEFAULT));
        assertTrue(error.getMessage().contains("no metric named 'nosuch'"), error.getMessage());
        assertTrue(error.getMessage().contains("Available metrics: constant, counting"), error.getMessage());
        // the registry knows no command line: it names the variable, cli adds its option
        assertTrue(error.getMessage().endsWith("(" + PluginRegistry.PLUGIN_PATH_VARIABLE + ")."), error.getMessage());
        assertFalse(error.getMessage().contains("--"), error.getMessage());
    }

    @Test
    void anUnknownOptionListsTheProvidersOptions() {
        PluginConfig config = PluginConfig.DEFAULT.withOptions(Map.of("scael", "3"));
        PluginException error = assertThrows(PluginException.class, () -> registry.metric("counting", config));
        assertTrue(error.getMessage().contains("has no option 'scael'; its options: scale"), error.getMessage());
    }

    @Test
    void listsEveryProviderWithItsOrigin() {
        List<PluginInfo> metrics = registry.list().stream().filter(i -> i.kind() == PluginKind.METRIC).toList();
        assertEquals(List.of("constant", "counting"), metrics.stream().map(PluginInfo::name).toList());
        assertEquals(Map.of("scale", "multiplies the count"), metrics.get(1).options());
        assertTrue(!metrics.get(0).origin().isEmpty());
    }

    @Test
    void twoProvidersWithOneNameAreAnError(@TempDir Path dir) throws IOException {
        Path services = dir.resolve("META-INF/services/org.scenes.api.MetricProvider");
        Files.createDirectories(services.getParent());
        Files.writeString(services, "org.scenes.api.TestMetrics$CountingTwin\n");
        ClassLoader loader = new URLClassLoader(new URL[] {dir.toUri().toURL()}, getClass().getClassLoader());

        PluginException error = assertThrows(PluginException.class, () -> PluginRegistry.load(loader));

        assertTrue(error.getMessage().contains("two metric plugins are named 'counting'"), error.getMessage());
    }

    @Test
    void aProviderDeclaresTheDimensionsTuneMaySearch() {
        TuneDimension scale = registry.tuneDimensions(PluginKind.METRIC, "counting").get("scale");
        assertEquals(List.of(0.0, 1.0, 10.0), scale.values());
        assertEquals(TuneDimension.Scale.LOG, scale.scale());
        assertEquals(10.0, scale.max());
        assertTrue(registry.tuneDimensions(PluginKind.METRIC, "constant").isEmpty());
    }

    @Test
    void aTuneDimensionThatIsNoOptionIsAnError(@TempDir Path dir) throws IOException {
        Path services = dir.resolve("META-INF/services/org.scenes.api.MetricProvider");
        Files.createDirectories(services.getParent());
        Files.writeString(services, "org.scenes.api.TestMetrics$Misdeclared\n");
        ClassLoader loader = new URLClassLoader(new URL[] {dir.toUri().toURL()}, getClass().getClassLoader());

        PluginException error = assertThrows(PluginException.class, () -> PluginRegistry.load(loader));

        assertTrue(error.getMessage().contains("'misdeclared'") && error.getMessage().contains("tune dimension 'scal'"),
                error.getMessage());
    }

    @Test
    void aLogDimensionTakesNoNegativeValues() {
        assertThrows(IllegalArgumentException.class, () -> TuneDimension.log("scale", -1, 1));
        assertThrows(IllegalArgumentException.class, () -> TuneDimension.linear("cycles"));
        assertEquals(-1.0, TuneDimension.linear("cycles", -1, 1, 2).min());
    }

    @Test
    void aMissingPluginDirectoryIsNamed(@TempDir Path dir) {
        Path missing = dir.resolve("nope");
        PluginException error = assertThrows(PluginException.class, () -> PluginRegistry.load(List.of(missing)));
        assertTrue(error.getMessage().contains(missing.toString()), error.getMessage());
    }

    @Test
    void pluginPathTextSplitsOnThePathSeparator() {
        String text = "/a" + java.io.File.pathSeparator + java.io.File.pathSeparator + "/b";
        assertEquals(List.of(Path.of("/a"), Path.of("/b")), PluginRegistry.parsePluginPath(text));
        assertEquals(List.of(), PluginRegistry.parsePluginPath(null));
    }
}
