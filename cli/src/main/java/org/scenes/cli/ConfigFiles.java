package org.scenes.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.files.AtomicOutput;
import org.scenes.files.Inputs;
import org.scenes.match.ActionWeights;
import org.scenes.match.ObjectWeights;
import org.scenes.validate.MatchConfig;

/** Reads and writes the matching configuration files of {@code scenes tune} and {@code --config}. */
final class ConfigFiles {
    static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ConfigFiles() {
    }

    static void write(Path file, MatchConfig config, Map<String, Object> extra) throws IOException {
        Map<String, Object> map = new LinkedHashMap<>(toMap(config));
        map.putAll(extra);
        try (AtomicOutput output = AtomicOutput.create(file)) {
            JSON.writeValue(output.stream(), map);
            output.commit();
        }
    }

    static Map<String, Object> toMap(MatchConfig config) {
        Map<String, Object> map = new LinkedHashMap<>();
        map.put("metric", config.metric());
        map.put("options", new java.util.TreeMap<>(config.metricOptions()));
        map.put("objectWeights", config.objectWeights().format());
        map.put("actionWeights", config.actionWeights().format());
        map.put("k", config.k());
        map.put("selector", config.selector());
        map.put("selectorOptions", new java.util.TreeMap<>(config.selectorOptions()));
        map.put("transforms", config.transforms());
        map.put("seed", config.seed());
        return map;
    }

    static MatchConfig read(Path file) {
        JsonNode root;
        try (var in = Inputs.open(file)) {
            root = JSON.readTree(in);
        } catch (IOException e) {
            throw new UsageException(file + ": not a readable configuration: " + e.getMessage());
        }
        if (!(root instanceof ObjectNode)) {
            throw new UsageException(file + ": a configuration is a JSON object");
        }
        try {
            MatchConfig base = MatchConfig.DEFAULT;
            return new MatchConfig(
                    text(root, "metric", base.metric()),
                    strings(root.get("options")),
                    root.has("objectWeights") ? ObjectWeights.parse(root.get("objectWeights").asText()) : base.objectWeights(),
                    root.has("actionWeights") ? ActionWeights.parse(root.get("actionWeights").asText()) : base.actionWeights(),
                    root.path("k").asInt(base.k()),
                    text(root, "selector", base.selector()),
                    strings(root.get("selectorOptions")),
                    list(root.get("transforms")),
                    root.path("seed").asLong(base.seed()));
        } catch (IllegalArgumentException e) {
            throw new UsageException(file + ": " + e.getMessage());
        }
    }

    private static String text(JsonNode root, String field, String fallback) {
        JsonNode node = root.get(field);
        return node == null || node.isNull() ? fallback : node.asText();
    }

    private static Map<String, String> strings(JsonNode node) {
        Map<String, String> map = new LinkedHashMap<>();
        if (node != null && node.isObject()) {
            node.fields().forEachRemaining(e -> map.put(e.getKey(), e.getValue().asText()));
        }
        return map;
    }

    private static List<String> list(JsonNode node) {
        List<String> list = new ArrayList<>();
        if (node != null && node.isArray()) {
            node.forEach(n -> list.add(n.asText()));
        }
        return list;
    }
}
