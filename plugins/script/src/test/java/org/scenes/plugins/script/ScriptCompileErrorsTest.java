package org.scenes.plugins.script;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;

/** Scripts that must not compile fail at creation, before any work, naming file, line and column. */
class ScriptCompileErrorsTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    @TempDir
    Path dir;

    private String write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text).toString();
    }

    /** The error lines of a metric script that does not compile, after the heading line. */
    private String[] metricErrors(String name, String text) throws IOException {
        String path = write(name, text);
        PluginException e = assertThrows(PluginException.class, () -> REGISTRY.metric("script:" + path, PluginConfig.DEFAULT));
        String[] lines = e.getMessage().split("\n");
        assertEquals("the metric script " + path + " does not compile:", lines[0]);
        String[] errors = new String[lines.length - 1];
        for (int i = 1; i < lines.length; i++) {
            errors[i - 1] = lines[i].strip().replace(path, name);
        }
        return errors;
    }

    @Test
    void syntaxErrorNamesFileLineAndColumn() throws IOException {
        String[] errors = metricErrors("broken.groovy", """
                double distance(Scene query, Scene stored) {
                    double d = (1 + 2
                    return d
                }
                """);
        assertEquals(1, errors.length);
        assertTrue(errors[0].startsWith("broken.groovy:3:12: Unexpected input"), errors[0]);
    }

    @Test
    void typeErrorIsFoundAtCompileTimeOncePerLine() throws IOException {
        String[] errors = metricErrors("typo.groovy", """
                double distance(Scene query, Scene stored) {
                    return query.objects().size() - stored.objcts().size()
                }
                """);
        assertEquals(1, errors.length, String.join("\n", errors));
        assertTrue(errors[0].startsWith("typo.groovy:2:50: [Static type checking] - Cannot find matching method "
                + "org.scenes.api.Scene#objcts()"), errors[0]);
    }

    @Test
    void wrongReturnTypeIsATypeError() throws IOException {
        String[] errors = metricErrors("text.groovy", """
                double distance(Scene query, Scene stored) {
                    Scene other = query.cycle()
                    return 0
                }
                """);
        assertTrue(errors[0].startsWith("text.groovy:2:"), errors[0]);
        assertTrue(errors[0].contains("Cannot assign value of type int to variable of type org.scenes.api.Scene"), errors[0]);
    }

    @Test
    void propertyStyleAccessToARecordGetsAHint() throws IOException {
        String[] errors = metricErrors("property.groovy", """
                double distance(Scene query, Scene stored) {
                    return query.cycle - stored.cycle()
                }
                """);
        assertEquals("property.groovy:2:12: Access to org.scenes.api.Scene#cycle is forbidden (scene values are "
                + "Java records: read them with cycle())", errors[0]);
    }

    @Test
    void systemExitIsRejected() throws IOException {
        String[] errors = metricErrors("exit.groovy", """
                double distance(Scene query, Scene stored) {
                    if (query.objects().isEmpty()) {
                        System.exit(1)
                    }
                    return 0
                }
                """);
        assertEquals("exit.groovy:3:9: System.exit would stop the whole program; a script reports a problem "
                + "by throwing an exception instead", errors[0]);
    }

    @Test
    void haltThroughAVariableAndExitThroughAPointerAreRejected() throws IOException {
        String[] errors = metricErrors("halt.groovy", """
                double distance(Scene query, Scene stored) {
                    Runtime runtime = Runtime.getRuntime()
                    runtime.halt(3)
                    def stop = System.&exit
                    return 0
                }
                """);
        assertEquals(2, errors.length, String.join("\n", errors));
        assertTrue(errors[0].startsWith("halt.groovy:3:5: Runtime.halt would stop the whole program"), errors[0]);
        assertTrue(errors[1].startsWith("halt.groovy:4:16: System.exit would stop the whole program"), errors[1]);
    }

    @Test
    void grabIsRejected() throws IOException {
        String[] errors = metricErrors("grab.groovy", """
                @Grab('org.apache.commons:commons-math3:3.6.1')
                import org.apache.commons.math3.util.FastMath

                double distance(Scene query, Scene stored) {
                    return 0
                }
                """);
        assertEquals("grab.groovy:1:1: @Grab is not allowed: scripts do not download libraries", errors[0]);
    }

    @Test
    void missingMethodSaysWhatToWrite() throws IOException {
        String[] errors = metricErrors("misspelt.groovy", """
                double distanc(Scene query, Scene stored) {
                    return 0
                }
                """);
        assertEquals("misspelt.groovy:1:1: a metric script must define the method double distance(Scene query, "
                + "Scene stored), or double[] encode(Scene scene) with double distance(double[] query, double[] stored, "
                + "double bound), at its top level", errors[0]);
    }

    @Test
    void fastFormNeedsBothMethods() throws IOException {
        String[] errors = metricErrors("half.groovy", """
                double[] encode(Scene scene) {
                    return new double[] {scene.objects().size()}
                }
                """);
        assertEquals("half.groovy:1:1: a metric script with encode must also define double distance(double[] query, "
                + "double[] stored, double bound) at its top level", errors[0]);
    }

    @Test
    void selectorScriptNeedsSelect() throws IOException {
        String path = write("metric-as-selector.groovy", "double distance(Scene query, Scene stored) { 0 }\n");
        PluginException e = assertThrows(PluginException.class, () -> REGISTRY.selector("script:" + path, PluginConfig.DEFAULT));
        assertTrue(e.getMessage().contains("a selector script must define the method Action select(List<Neighbour> nearest, "
                + "RandomGenerator random)"), e.getMessage());
    }

    @Test
    void missingFileIsAClearError() {
        Path missing = dir.resolve("nowhere/metric.groovy");
        PluginException e = assertThrows(PluginException.class,
                () -> REGISTRY.metric("script:" + missing, PluginConfig.DEFAULT));
        assertEquals("the metric script " + missing + " does not exist (looked in " + missing + ")", e.getMessage());
    }

    @Test
    void missingPathSaysHowToWriteIt() {
        PluginException e = assertThrows(PluginException.class, () -> REGISTRY.selector("script", PluginConfig.DEFAULT));
        assertEquals("the selector script needs a file: script:PATH, e.g. script:examples/scripts/vote.groovy", e.getMessage());
    }
}
