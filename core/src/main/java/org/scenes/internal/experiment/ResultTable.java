package org.scenes.internal.experiment;

import com.fasterxml.jackson.core.JsonEncoding;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.validate.Folds;

/**
 * The results of a sweep: one row per configuration with every measure (the CSV and JSON
 * files), and the pivot the sweep's layout asks for (the form of the thesis' tables and of the
 * chart).
 */
public final class ResultTable {
    private final Sweep sweep;
    private final List<Result> results;

    public ResultTable(Sweep sweep, List<Result> results) {
        if (results.size() != sweep.configurations().size()) {
            throw new IllegalArgumentException("a sweep of " + sweep.configurations().size() + " configurations has "
                    + results.size() + " results");
        }
        this.sweep = sweep;
        this.results = List.copyOf(results);
    }

    public Sweep sweep() {
        return sweep;
    }

    /** One result per configuration, in sweep order. */
    public List<Result> results() {
        return results;
    }

    /** Names of the measures, in the validator's order. */
    public List<String> measures() {
        return results.isEmpty() ? List.of() : List.copyOf(results.get(0).measures().keySet());
    }

    /** The rows' labels: the row axes' values, joined with " / " when there are several. */
    public List<String> rowValues() {
        List<String> labels = new ArrayList<>();
        for (Result result : results) {
            String label = rowLabel(result.configuration());
            if (!labels.contains(label)) {
                labels.add(label);
            }
        }
        return labels;
    }

    private String rowLabel(Configuration configuration) {
        List<String> parts = new ArrayList<>();
        for (Axis axis : sweep.layout().rows()) {
            parts.add(configuration.value(axis));
        }
        return String.join(" / ", parts);
    }

    /** The columns' labels: the column axis' values, or the measures' names. */
    public List<String> columnValues() {
        Sweep.Layout layout = sweep.layout();
        return layout.columnsAreMeasures() ? layout.measures() : sweep.values(layout.columns());
    }

    /** The value shown for one row and column label. */
    public double cell(String row, String column) {
        Sweep.Layout layout = sweep.layout();
        for (Result result : results) {
            Configuration configuration = result.configuration();
            if (!rowLabel(configuration).equals(row)) {
                continue;
            }
            if (layout.columnsAreMeasures()) {
                return result.measure(column);
            }
            if (configuration.value(layout.columns()).equals(column)) {
                return result.measure(layout.measures().get(0));
            }
        }
        throw new IllegalArgumentException("no result for " + Sweep.keys(layout.rows()) + " " + row + " and "
                + layout.columnsKey() + " " + column);
    }

    /** Checks the layout's measures exist, before anyone draws or prints the pivot. */
    public void checkMeasures() {
        if (!results.isEmpty()) {
            for (String measure : sweep.layout().measures()) {
                results.get(0).measure(measure);
            }
        }
    }

    /** The CSV table's header: the axes, then the measures. */
    public List<String> csvHeader() {
        List<String> header = new ArrayList<>();
        for (Axis axis : Axis.values()) {
            header.add(axis.key());
        }
        header.addAll(measures());
        return header;
    }

    /**
     * Every configuration and measure, one row each, as the cells of the CSV table (numbers in
     * full precision so files compare exactly, empty where a measure is undefined); the CLI writes
     * them through a CSV library.
     */
    public List<List<String>> csvRows() {
        List<List<String>> rows = new ArrayList<>();
        for (Result result : results) {
            List<String> cells = new ArrayList<>();
            for (Axis axis : Axis.values()) {
                cells.add(result.configuration().value(axis));
            }
            for (String measure : measures()) {
                cells.add(number(result.measure(measure)));
            }
            rows.add(cells);
        }
        return rows;
    }

    private static String number(double value) {
        return Double.isNaN(value) ? "" : Double.toString(value);
    }

    /**
     * The sweep, every result and the pivot.
     *
     * @param command the command line that produced it, so the file says how to regenerate it
     */
    public void writeJson(Path file, String command) throws IOException {
        try (AtomicOutput output = AtomicOutput.create(file);
             JsonGenerator json = new JsonFactory().createGenerator(output.stream(), JsonEncoding.UTF8)) {
            json.useDefaultPrettyPrinter();
            json.writeStartObject();
            json.writeStringField("title", sweep.title());
            json.writeStringField("command", command);
            json.writeObjectFieldStart("sweep");
            json.writeArrayFieldStart("data");
            for (String data : sweep.data()) {
                json.writeString(data);
            }
            json.writeEndArray();
            for (Axis axis : Axis.values()) {
                json.writeArrayFieldStart(axis.key());
                for (String value : sweep.values(axis)) {
                    if (axis == Axis.K) {
                        json.writeNumber(Integer.parseInt(value));
                    } else {
                        json.writeString(value);
                    }
                }
                json.writeEndArray();
            }
            json.writeStringField("protocol", sweep.protocol().key());
            json.writeArrayFieldStart("transforms");
            for (String transform : sweep.transforms()) {
                json.writeString(transform);
            }
            json.writeEndArray();
            json.writeNumberField("seed", sweep.seed());
            json.writeEndObject();
            json.writeArrayFieldStart("results");
            for (Result result : results) {
                json.writeStartObject();
                for (Axis axis : Axis.values()) {
                    String value = result.configuration().value(axis);
                    if (axis == Axis.K) {
                        json.writeNumberField(axis.key(), Integer.parseInt(value));
                    } else {
                        json.writeStringField(axis.key(), value);
                    }
                }
                for (String measure : measures()) {
                    writeNumber(json, measure, result.measure(measure));
                }
                json.writeEndObject();
            }
            json.writeEndArray();
            Sweep.Layout layout = sweep.layout();
            json.writeObjectFieldStart("table");
            json.writeArrayFieldStart("rows");
            for (Axis axis : layout.rows()) {
                json.writeString(axis.key());
            }
            json.writeEndArray();
            json.writeStringField("columns", layout.columnsKey());
            json.writeArrayFieldStart("measures");
            for (String measure : layout.measures()) {
                json.writeString(measure);
            }
            json.writeEndArray();
            json.writeArrayFieldStart("rowValues");
            for (String row : rowValues()) {
                json.writeString(row);
            }
            json.writeEndArray();
            json.writeArrayFieldStart("columnValues");
            for (String column : columnValues()) {
                json.writeString(column);
            }
            json.writeEndArray();
            json.writeArrayFieldStart("cells");
            for (String row : rowValues()) {
                json.writeStartArray();
                for (String column : columnValues()) {
                    double value = cell(row, column);
                    if (Double.isNaN(value)) {
                        json.writeNull();
                    } else {
                        json.writeNumber(value);
                    }
                }
                json.writeEndArray();
            }
            json.writeEndArray();
            json.writeEndObject();
            json.writeEndObject();
            json.flush();
            output.commit();
        }
    }

    private static void writeNumber(JsonGenerator json, String name, double value) throws IOException {
        if (Double.isNaN(value)) {
            json.writeNullField(name);
        } else {
            json.writeNumberField(name, value);
        }
    }

    /**
     * The Markdown page of a sweep's results: heading, how to regenerate it, the protocol and the pivot.
     *
     * @param command the command line that produced it
     * @param chart the chart's file name, linked below the table, or null for none
     */
    public String markdownDocument(String fallbackTitle, String command, String chart) {
        StringBuilder text = new StringBuilder();
        text.append("# ").append(sweep.title().isEmpty() ? fallbackTitle : sweep.title()).append("\n\n");
        text.append("Regenerate with `").append(command).append("` (sweep script, data and protocol: ")
                .append("docs/scripting.md). Cross-validation over ").append(sweep.data().size())
                .append(" scene files, each tested against ")
                .append(sweep.protocol() == Folds.Protocol.NEXT ? "the next one" : "all the others")
                .append("; seed ").append(sweep.seed());
        if (!sweep.transforms().isEmpty()) {
            text.append("; transforms ").append(String.join(", ", sweep.transforms()));
        }
        text.append(". Values are means over the folds of ").append(String.join(", ", sweep.layout().measures()))
                .append("; every measure of every configuration is in the CSV and JSON files beside this one.\n\n");
        text.append(markdown());
        if (chart != null) {
            text.append("\n![").append(sweep.title()).append("](").append(chart).append(")\n");
        }
        return text.toString();
    }

    /** The pivot as a Markdown table, values with four decimals. */
    public String markdown() {
        Sweep.Layout layout = sweep.layout();
        StringBuilder text = new StringBuilder();
        text.append("| ").append(String.join(" / ", layout.rows().stream().map(Axis::key).toList()))
                .append(" \\ ").append(layout.columnsKey());
        for (String column : columnValues()) {
            text.append(" | ").append(column);
        }
        text.append(" |\n|---");
        text.append("|---:".repeat(columnValues().size())).append("|\n");
        for (String row : rowValues()) {
            text.append("| ").append(row);
            for (String column : columnValues()) {
                double value = cell(row, column);
                text.append(" | ").append(Double.isNaN(value) ? "-" : String.format(Locale.ROOT, "%.4f", value));
            }
            text.append(" |\n");
        }
        return text.toString();
    }
}
