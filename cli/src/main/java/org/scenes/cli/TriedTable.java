package org.scenes.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.RandomSearch;

/** The table of configurations {@code scenes tune --table} writes: CSV (Commons CSV) or JSON, by the file's extension. */
final class TriedTable {
    static final List<String> COLUMNS = List.of("id", "rung", "queries", "score", "accuracy", "directionAccuracy", "macroF1",
            "metric", "options", "objectWeights", "k", "selector", "selectorOptions", "actionWeights", "transforms", "describe");

    private TriedTable() {
    }

    static void checkName(Path file) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!name.endsWith(".csv") && !name.endsWith(".json")) {
            throw new UsageException("--table " + file + ": name it FILE.csv or FILE.json");
        }
    }

    static void write(Path file, List<RandomSearch.Tried> rows) throws IOException {
        boolean csv = file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".csv");
        if (csv) {
            List<List<Object>> table = new ArrayList<>();
            rows.forEach(row -> table.add(new ArrayList<>(cells(row).values())));
            CsvTables.write(file, COLUMNS, table);
            return;
        }
        try (AtomicOutput output = AtomicOutput.create(file)) {
            List<Map<String, Object>> maps = new ArrayList<>();
            rows.forEach(row -> maps.add(cells(row)));
            ConfigFiles.JSON.writeValue(output.stream(), maps);
            output.commit();
        }
    }

    private static Map<String, Object> cells(RandomSearch.Tried row) {
        MatchConfig config = row.config();
        Map<String, Object> cells = new LinkedHashMap<>();
        cells.put("id", row.id());
        cells.put("rung", row.rung());
        cells.put("queries", row.queries());
        cells.put("score", row.score());
        cells.put("accuracy", row.accuracy());
        cells.put("directionAccuracy", row.directionAccuracy());
        cells.put("macroF1", row.macroF1());
        cells.put("metric", config.metric());
        cells.put("options", options(config.metricOptions()));
        cells.put("objectWeights", config.objectWeights().format());
        cells.put("k", config.k());
        cells.put("selector", config.selector());
        cells.put("selectorOptions", options(config.selectorOptions()));
        cells.put("actionWeights", config.actionWeights().format());
        cells.put("transforms", String.join(",", config.transforms()));
        cells.put("describe", config.describe());
        return cells;
    }

    private static String options(Map<String, String> options) {
        StringBuilder text = new StringBuilder();
        new TreeMap<>(options).forEach((key, value) -> text.append(text.length() == 0 ? "" : ",").append(key)
                .append('=').append(value));
        return text.toString();
    }
}
