package org.scenes.spark;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import org.scenes.api.PluginRegistry;
import picocli.CommandLine.Option;
import picocli.CommandLine.ScopeType;

/** Options every job accepts: where it runs, Spark properties, plugins. */
final class SparkOptions {
    @Option(names = "--master", scope = ScopeType.INHERIT, paramLabel = "URL",
            description = "Spark master: local[*] (every core of this machine; the default, unless spark-submit gave"
                    + " one), local[N], spark://HOST:PORT, yarn, k8s://...")
    String master;

    @Option(names = "--conf", scope = ScopeType.INHERIT, paramLabel = "KEY=VALUE",
            description = "A Spark property (repeatable), e.g. --conf spark.executor.memory=4g.")
    Map<String, String> properties = new LinkedHashMap<>();

    @Option(names = "--plugin-path", scope = ScopeType.INHERIT, paramLabel = "DIR",
            description = "Directory of plugin jars to load (repeatable; also the " + PluginRegistry.PLUGIN_PATH_VARIABLE
                    + " environment variable); on a cluster the same directory must exist on every executor.")
    List<Path> pluginPath = new ArrayList<>();

    @Option(names = "--verbose", scope = ScopeType.INHERIT, description = "Print stack traces of errors.")
    boolean verbose;

    private PluginRegistry registry;

    List<String> pluginDirectories() {
        List<String> directories = new ArrayList<>();
        pluginPath.forEach(path -> directories.add(path.toAbsolutePath().toString()));
        PluginRegistry.parsePluginPath(System.getenv(PluginRegistry.PLUGIN_PATH_VARIABLE))
                .forEach(path -> directories.add(path.toAbsolutePath().toString()));
        return directories;
    }

    /** The driver's registry (to check configurations before any task runs). */
    PluginRegistry registry() {
        if (registry == null) {
            registry = ExecutorState.registry(pluginDirectories());
        }
        return registry;
    }

    /** --master, else the master spark-submit set (as the spark.master property), else local[*]. */
    String master() {
        return master != null ? master : System.getProperty("spark.master", "local[*]");
    }

    boolean local() {
        return master().startsWith("local");
    }

    /**
     * The Spark context of a job. In local mode the driver and its executor threads listen on the
     * loopback interface only and the web UI is off (set spark.ui.enabled=true to have it); on a
     * cluster the project's jars are shipped to the executors.
     */
    JavaSparkContext start(String job) {
        SparkConf conf = new SparkConf().setAppName("scenes-spark " + job).setMaster(master());
        if (local()) {
            conf.set("spark.driver.host", "127.0.0.1").set("spark.driver.bindAddress", "127.0.0.1")
                    .set("spark.ui.enabled", "false");
        } else {
            List<String> jars = shippedJars();
            if (!jars.isEmpty()) {
                conf.set("spark.jars", String.join(",", jars));
            }
        }
        properties.forEach(conf::set);
        JavaSparkContext context = new JavaSparkContext(conf);
        context.setLogLevel("WARN");
        return context;
    }

    /** The jars on this JVM's class path that the build listed as needed by executors. */
    static List<String> shippedJars() {
        List<String> names = new ArrayList<>();
        try (InputStream in = SparkOptions.class.getResourceAsStream("ship.txt")) {
            if (in == null) {
                return names;
            }
            for (String line : new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\n")) {
                if (!line.isBlank()) {
                    names.add(line.trim());
                }
            }
        } catch (IOException e) {
            return List.of();
        }
        List<String> jars = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            Path path = Path.of(entry);
            if (path.getFileName() != null && names.contains(path.getFileName().toString())) {
                jars.add(path.toAbsolutePath().toUri().toString());
            }
        }
        return jars;
    }
}
