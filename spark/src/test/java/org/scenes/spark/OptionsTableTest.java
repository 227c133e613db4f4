package org.scenes.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.scenes.options.OptionsTable;

/** docs/options-spark.md is the table picocli's model of scenes-spark gives: it fails when an option changes and the table does not. */
class OptionsTableTest {
    static final String HEADER = "# Options of every scenes-spark job\n\n"
            + "Generated from the jobs' picocli model by `OptionsTableTest` (spark); do not edit by hand. After changing"
            + " an option, run `gradle -q :spark:test -Ponly='.*OptionsTableTest'` and copy the table it writes"
            + " (`spark/build/options-spark.md`) over this file. The `scenes` commands' options: [options.md](options.md).\n\n";

    @Test
    void theDocsTableIsTheOptionsOfEveryJob() throws Exception {
        String generated = HEADER + OptionsTable.markdown(SparkCommand.commandLine());
        Path root = Path.of(System.getProperty("scenes.root", "."));
        Path written = root.resolve("spark/build/options-spark.md");
        Files.createDirectories(written.getParent());
        Files.writeString(written, generated, StandardCharsets.UTF_8);
        Path docs = root.resolve("docs/options-spark.md");
        assertTrue(Files.exists(docs), docs + " is missing: copy " + written + " there");
        assertEquals(generated, Files.readString(docs, StandardCharsets.UTF_8),
                "docs/options-spark.md is stale: copy " + written + " over it");
        assertTrue(generated.contains("| --protocol | leave-one-out\\|next | leave-one-out |"), "tune's protocol");
    }
}
