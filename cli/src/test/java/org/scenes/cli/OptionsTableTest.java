package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.scenes.options.OptionsTable;

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
        Path root = Path.of(System.getProperty("scenes.root", "."));
        Path written = root.resolve("cli/build/options.md");
        Files.createDirectories(written.getParent());
        Files.writeString(written, generated, StandardCharsets.UTF_8);
        Path docs = root.resolve("docs/options.md");
        assertTrue(Files.exists(docs), docs + " is missing: copy " + written + " there");
        assertEquals(generated, Files.readString(docs, StandardCharsets.UTF_8),
                "docs/options.md is stale: copy " + written + " over it");
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
}
