package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.cli.Main;

/**
 * A metric compiled at test time into its own jar, never on the class path, is found by
 * name once its directory is on the plugin path: third-party plugins need no code change.
 */
class PluginPathTest {
    private static final String SOURCE = """
            package thirdparty;

            import org.scenes.api.MetricProvider;
            import org.scenes.api.SceneMetric;
            import org.scenes.api.PluginConfig;

            public final class ObjectCountMetric implements MetricProvider {
                public String name() { return "object-count"; }
                public String description() { return "difference in the number of seen objects"; }
                public SceneMetric create(PluginConfig config) {
                    return (query, stored) -> Math.abs(query.objects().size() - stored.objects().size());
                }
            }
            """;

    @TempDir
    static Path work;
    static Path pluginDir;

    @BeforeAll
    static void buildPluginJar() throws IOException {
        Path sources = Files.createDirectories(work.resolve("src/thirdparty"));
        Path classes = Files.createDirectories(work.resolve("classes"));
        Path source = sources.resolve("ObjectCountMetric.java");
        Files.writeString(source, SOURCE);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        StringWriter diagnostics = new StringWriter();
        int status = javac.run(null, null, new StringOutputStream(diagnostics), "--release", "17",
                "-classpath", System.getProperty("java.class.path"), "-d", classes.toString(), source.toString());
        assertEquals(0, status, diagnostics.toString());

        pluginDir = Files.createDirectories(work.resolve("plugins"));
        try (JarOutputStream jar = new JarOutputStream(Files.newOutputStream(pluginDir.resolve("object-count.jar")))) {
            jar.putNextEntry(new JarEntry("thirdparty/ObjectCountMetric.class"));
            jar.write(Files.readAllBytes(classes.resolve("thirdparty/ObjectCountMetric.class")));
            jar.putNextEntry(new JarEntry("META-INF/services/org.scenes.api.MetricProvider"));
            jar.write("thirdparty.ObjectCountMetric\n".getBytes(StandardCharsets.UTF_8));
        }
    }

    @Test
    void theJarIsNotVisibleWithoutThePluginPath() {
        PluginException error = assertThrows(PluginException.class,
                () -> PluginRegistry.load().metric("object-count", PluginConfig.DEFAULT));
        assertTrue(error.getMessage().contains("no metric named 'object-count'"), error.getMessage());
    }

    @Test
    void aMetricInAJarOnThePluginPathIsUsedByName() {
        SceneMetric metric = PluginRegistry.load(List.of(pluginDir)).metric("object-count", PluginConfig.DEFAULT);
        SeenObject ball = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 3, 0, Grid.DEFAULT);
        Scene one = new Scene(1, null, List.of(ball), List.of());
        Scene three = new Scene(2, null, List.of(ball, ball, ball), List.of());

        assertEquals(2.0, metric.distance(one, three));
        assertFalse(metric.getClass().getName().startsWith("org.scenes"));
    }

    @Test
    void scenesPluginsListsTheJarAndItsOrigin() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();

        int status = Main.run(new PrintWriter(out), new PrintWriter(err), "plugins", "--plugin-path", pluginDir.toString());

        assertEquals(0, status, err.toString());
        String line = out.toString().lines().filter(l -> l.contains("object-count")).findFirst().orElse("");
        assertTrue(line.contains("difference in the number of seen objects"), out.toString());
        assertTrue(line.contains("[object-count.jar]"), line);
    }

    /** Lets javac report into a StringWriter. */
    private static final class StringOutputStream extends OutputStream {
        private final StringWriter target;

        StringOutputStream(StringWriter target) {
            this.target = target;
        }

        @Override
        public void write(int b) {
            target.write(b);
        }
    }
}
