package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class TerminalProgressTest {
    @Test
    void withoutATerminalNothingIsDrawn() {
        assertNull(System.console(), "tests run without a terminal");
        PrintStream err = System.err;
        ByteArrayOutputStream written = new ByteArrayOutputStream();
        System.setErr(new PrintStream(written, true, StandardCharsets.UTF_8));
        try (TerminalProgress bar = TerminalProgress.start("Testing", 10, " steps", 1)) {
            assertFalse(bar.shown());
            bar.step();
            bar.stepBy(3);
            bar.stepTo(7);
            bar.stepper().accept(9);
            bar.maxHint(20);
            bar.message("best 0.5");
        } finally {
            System.setErr(err);
        }
        assertFalse(TerminalProgress.none().shown());
        assertFalse(written.size() > 0, written.toString(StandardCharsets.UTF_8));
    }
}
