package org.scenes.spark;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.scenes.options.OptionsTable;
import org.scenes.testing.GeneratedDocs;

/** docs/options-spark.md is the table picocli's model of scenes-spark gives: it fails when an option changes and the table does not. */
class OptionsTableTest {
    static final String HEADER = "# Options of every scenes-spark job\n\n"
            + "Generated from the jobs' picocli model by `OptionsTableTest` (spark); do not edit by hand. After changing"
            + " an option, run `gradle -q :spark:test -Ponly='.*OptionsTableTest'` and copy the table it writes"
            + " (`spark/build/options-spark.md`) over this file. The `scenes` commands' options: [options.md](options.md).\n\n";

    @Test
    void theDocsTableIsTheOptionsOfEveryJob() throws Exception {
        String generated = HEADER + OptionsTable.markdown(SparkCommand.commandLine());
        GeneratedDocs.assertCurrent(generated, "spark/build/options-spark.md", "docs/options-spark.md");
        assertTrue(generated.contains("| --protocol | leave-one-out\\|next | leave-one-out |"), "tune's protocol");
    }
}
