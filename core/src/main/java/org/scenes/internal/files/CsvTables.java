package org.scenes.internal.files;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVPrinter;

/**
 * The project's one CSV codec: tables through Apache Commons CSV (RFC 4180 quoting, '\n' line
 * ends), written atomically. Results, exports and tuner tables all use it.
 */
public final class CsvTables {
    private CsvTables() {
    }

    /** A printer with this header over {@code out}; the caller flushes it. */
    public static CSVPrinter printer(Writer out, List<String> header) throws IOException {
        return new CSVPrinter(out, CSVFormat.DEFAULT.builder().setHeader(header.toArray(String[]::new))
                .setRecordSeparator('\n').build());
    }

    /** The header and rows written to a temporary file renamed over {@code file} when complete. */
    public static void write(Path file, List<String> header, List<? extends List<?>> rows) throws IOException {
        try (AtomicOutput output = AtomicOutput.create(file)) {
            Writer writer = new BufferedWriter(new OutputStreamWriter(output.stream(), StandardCharsets.UTF_8));
            CSVPrinter printer = printer(writer, header);
            for (List<?> row : rows) {
                printer.printRecord(row);
            }
            printer.flush();
            output.commit();
        }
    }
}
