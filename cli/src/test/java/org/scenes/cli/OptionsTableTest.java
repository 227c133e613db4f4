package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import org.scenes.options.OptionsTable;
import org.scenes.testing.GeneratedDocs;

/** docs/options.md is the table picocli's model gives: it fails when an option changes and the table does not. */
class OptionsTableTest {
    static final String HEADER = "# Options of every command\n\n"
            + "Generated from the commands' picocli model by `OptionsTableTest` (cli); do not edit by hand. After changing"
            + " an option, run `gradle -q :cli:test -Ponly='.*OptionsTableTest'` and copy the table it writes"
            + " (`cli/build/options.md`) over this file. The help and version options (`-h, --help`, `-V, --version`) are"
            + " left out.\n\n";

    @Test
    void theDocsTableIsTheOptionsOfEveryCommand() throws Exception {
        String generated = HEADER + OptionsTable.markdown(ScenesCommand.commandLine());
        GeneratedDocs.assertCurrent(generated, "cli/build/options.md", "docs/options.md");
    }

    @Test
    void everyCommandWithOptionsHasItsTable() {
        String table = OptionsTable.markdown(ScenesCommand.commandLine());
        for (String command : ScenesCommand.commandLine().getSubcommands().keySet()) {
            if (!command.equals("help")) {
                assertTrue(table.contains("## scenes " + command + "\n"), command);
            }
        }
        assertTrue(table.contains("| --game-seed, --seed | N | 1 |"), "simulate's seed and its older spelling");
        assertTrue(table.contains("| --protocol | next\\|leave-one-out | next |"), "validate's protocol");
        assertTrue(table.contains("| --protocol | leave-one-out\\|next | leave-one-out |"), "tune's protocol");
    }

    @Test
    void everyHelpRendersWithoutAWarning() {
        // picocli passes each description line through String.format (for %n): a lone '%' prints a
        // warning and the raw line in the help; write '%%'
        PrintStream saved = System.err;
        ByteArrayOutputStream warnings = new ByteArrayOutputStream();
        System.setErr(new PrintStream(warnings, true, StandardCharsets.UTF_8));
        try {
            for (CommandLine command : ScenesCommand.commandLine().getSubcommands().values()) {
                command.getUsageMessage();
            }
        } finally {
            System.setErr(saved);
        }
        String printed = warnings.toString(StandardCharsets.UTF_8);
        assertFalse(printed.contains("WARN"), printed);
    }
}
