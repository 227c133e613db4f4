package org.scenes.internal.validate;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.protocol.ViewWidth;
import org.scenes.internal.target.Replay;

/**
 * The configuration file of {@code scenes tune} and {@code scenes-spark tune}, read by {@code --config}:
 * a JSON object of {@link MatchConfig}'s fields, and what tune writes beside them ({@code crossValidation}).
 * The one reader and writer of the format.
 */
public final class MatchConfigFile {
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    /** The keys a configuration may hold; {@code crossValidation} is what tune writes beside them. */
    public static final List<String> KEYS = List.of("metric", "options", "objectWeights", "actionWeights", "k",
            "selector", "selectorOptions", "transforms", "seed", "replay", "view", "crossValidation");

    /** A configuration file that cannot be read; the message starts with the file's name. */
    public static final class InvalidException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        InvalidException(String message) {
            super(message);
        }
    }

    private MatchConfigFile() {
    }

    /** Writes {@code config} and then the {@code extra} keys to {@code file}, atomically. */
    public static void write(Path file, MatchConfig config, Map<String, Object> extra) throws IOException {
        try (AtomicOutput output = AtomicOutput.create(file)) {
            write(output.stream(), config, extra);
            output.commit();
        }
    }

    /** Writes {@code config} and then the {@code extra} keys to {@code out}, and closes it. */
    public static void write(OutputStream out, MatchConfig config, Map<String, Object> extra) throws IOException {
        Map<String, Object> map = new LinkedHashMap<>(toMap(config));
        map.putAll(extra);
        JSON.writeValue(out, map);
    }

    /** The configuration's keys in the file's order (also the {@code config} block of validate's report). */
    public static Map<String, Object> toMap(MatchConfig config) {
        Map<String, Object> map = new LinkedHashMap<>();
        map.put("metric", config.metric());
        map.put("options", new TreeMap<>(config.metricOptions()));
        map.put("objectWeights", config.objectWeights().format());
        map.put("actionWeights", config.actionWeights().format());
        map.put("k", config.k());
        map.put("selector", config.selector());
        map.put("selectorOptions", new TreeMap<>(config.selectorOptions()));
        map.put("transforms", config.transforms());
        map.put("seed", config.seed());
        map.put("replay", config.replay().key());
        if (config.view() != null) {
            map.put("view", config.view().key());
        }
        return map;
    }

    /**
     * Reads a configuration; keys left out take {@link MatchConfig#DEFAULT}'s values.
     *
     * @throws InvalidException naming the file (and the key, or the line and column) for a missing
     *     file, text that is not JSON, or a key that is unknown or of the wrong type
     */
    public static MatchConfig read(Path file) {
        if (!Files.exists(file)) {
            throw new InvalidException(file + ": no such configuration file");
        }
        JsonNode root;
        try (var in = Inputs.open(file)) {
            root = JSON.readTree(in);
        } catch (JsonProcessingException e) {
            JsonLocation at = e.getLocation();
            throw new InvalidException(file + (at == null ? "" : ":" + at.getLineNr() + ":" + at.getColumnNr())
                    + ": not a valid configuration (JSON): " + e.getOriginalMessage());
        } catch (IOException e) {
            throw new InvalidException(file + ": not a readable configuration: " + e.getMessage());
        }
        if (!(root instanceof ObjectNode)) {
            throw new InvalidException(file + ": a configuration is a JSON object");
        }
        root.fieldNames().forEachRemaining(key -> {
            if (!KEYS.contains(key)) {
                throw new InvalidException(file + ": unknown key '" + key + "' (known: " + String.join(", ", KEYS) + ")");
            }
        });
        try {
            MatchConfig base = MatchConfig.DEFAULT;
            return new MatchConfig(
                    text(file, root, "metric", base.metric()),
                    strings(file, root, "options"),
                    root.has("objectWeights") ? ObjectWeights.parse(text(file, root, "objectWeights", "")) : base.objectWeights(),
                    root.has("actionWeights") ? ActionWeights.parse(text(file, root, "actionWeights", "")) : base.actionWeights(),
                    (int) integer(file, root, "k", base.k(), Integer.MIN_VALUE, Integer.MAX_VALUE),
                    text(file, root, "selector", base.selector()),
                    strings(file, root, "selectorOptions"),
                    list(file, root, "transforms"),
                    integer(file, root, "seed", base.seed(), Long.MIN_VALUE, Long.MAX_VALUE),
                    Replay.parse(text(file, root, "replay", base.replay().key())),
                    root.hasNonNull("view") ? ViewWidth.parse(text(file, root, "view", "")) : base.view());
        } catch (IllegalArgumentException e) {
            throw new InvalidException(file + ": " + e.getMessage());
        }
    }

    private static InvalidException wrongType(Path file, String key, String expected, JsonNode node) {
        return new InvalidException(file + ": key '" + key + "' must be " + expected + ", not " + node);
    }

    private static String text(Path file, JsonNode root, String field, String fallback) {
        JsonNode node = root.get(field);
        if (node == null || node.isNull()) {
            return fallback;
        }
        if (!node.isTextual()) {
            throw wrongType(file, field, "a string", node);
        }
        return node.asText();
    }

    private static long integer(Path file, JsonNode root, String field, long fallback, long min, long max) {
        JsonNode node = root.get(field);
        if (node == null || node.isNull()) {
            return fallback;
        }
        if (!node.isIntegralNumber() || !node.canConvertToLong() || node.asLong() < min || node.asLong() > max) {
            throw wrongType(file, field, "an integer", node);
        }
        return node.asLong();
    }

    private static Map<String, String> strings(Path file, JsonNode root, String field) {
        JsonNode node = root.get(field);
        Map<String, String> map = new LinkedHashMap<>();
        if (node == null || node.isNull()) {
            return map;
        }
        if (!node.isObject()) {
            throw wrongType(file, field, "an object of option values", node);
        }
        var fields = node.fields();
        while (fields.hasNext()) {
            var entry = fields.next();
            if (!entry.getValue().isValueNode() || entry.getValue().isNull()) {
                throw wrongType(file, field + "." + entry.getKey(), "a string or number", entry.getValue());
            }
            map.put(entry.getKey(), entry.getValue().asText());
        }
        return map;
    }

    private static List<String> list(Path file, JsonNode root, String field) {
        JsonNode node = root.get(field);
        List<String> list = new ArrayList<>();
        if (node == null || node.isNull()) {
            return list;
        }
        if (!node.isArray()) {
            throw wrongType(file, field, "an array of names", node);
        }
        for (JsonNode item : node) {
            if (!item.isTextual()) {
                throw wrongType(file, field, "an array of names", node);
            }
            list.add(item.asText());
        }
        return list;
    }
}
