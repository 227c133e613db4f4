package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The options whose values are names (enum converters): a bad name is a usage error naming the option and the names. */
class OptionValuesTest {
    private final CommandRunner cli = new CommandRunner();

    private void refused(String option, String expected, Object... args) {
        assertEquals(ExitCodes.USAGE, cli.run(args), cli.err());
        assertTrue(cli.err().contains("'" + option + "'") && cli.err().contains(expected), cli.err());
    }

    @Test
    void aBadNameIsAUsageErrorNamingTheOptionAndTheNames() {
        refused("--protocol", "expected next or leave-one-out, not 'sideways'",
                "validate", "--folds", "a.json", "b.json", "--protocol", "sideways");
        refused("--protocol", "expected next or leave-one-out, not 'next-one'",
                "tune", "--train", "a.json", "b.json", "-o", "c.json", "--protocol", "next-one");
        refused("--objective", "expected mean, accuracy, direction or macro-f1, not 'f1'",
                "tune", "--train", "a.json", "b.json", "-o", "c.json", "--objective", "f1");
        refused("--key-by", "expected influence or events, not 'kicks'",
                "show", "a.json", "--key-scenes", "3", "--key-by", "kicks");
        refused("--key-by", "expected influence or events, not 'kicks'",
                "export", "a.json", "--format", "csv", "--key-by", "kicks");
        refused("--commands", "expected rcl, infer or auto, not 'guess'",
                "convert", "g.rcg", "--out-dir", "s", "--commands", "guess");
    }
}
