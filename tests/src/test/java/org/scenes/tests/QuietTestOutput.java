package org.scenes.tests;

import com.code_intelligence.jazzer.utils.Log;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.junit.platform.launcher.LauncherSession;
import org.junit.platform.launcher.LauncherSessionListener;

/**
 * Keeps the test engines' information lines off the console of {@code gradle test}: Jazzer's
 * "INFO: Loaded N hooks" and "INFO: Instrumented class" (dozens per run of the regression tests)
 * and jqwik's "Edge case generation exceeds number of tries"; warnings and errors still print.
 * Fuzzing ({@code JAZZER_FUZZ=1}) prints everything. Registered through META-INF/services, so the
 * JUnit launcher opens it before any test runs.
 */
public final class QuietTestOutput implements LauncherSessionListener {
    /** Held here: java.util.logging keeps loggers only weakly, and a collected one forgets its level. */
    private static final Logger JQWIK = Logger.getLogger("net.jqwik");

    @Override
    public void launcherSessionOpened(LauncherSession session) {
        JQWIK.setLevel(Level.WARNING);
        if (System.getenv("JAZZER_FUZZ") == null) {
            Log.fixOutErr(System.out, new PrintStream(new InfoLineFilter(System.err), true, StandardCharsets.UTF_8));
        }
    }

    /** Passes whole lines to the stream underneath, except those starting with "INFO: ". */
    private static final class InfoLineFilter extends OutputStream {
        private final PrintStream target;
        private final StringBuilder line = new StringBuilder();

        InfoLineFilter(PrintStream target) {
            this.target = target;
        }

        @Override
        public synchronized void write(int b) {
            line.append((char) b);
            if (b == '\n') {
                if (!line.toString().startsWith("INFO: ")) {
                    target.print(line);
                    target.flush();
                }
                line.setLength(0);
            }
        }
    }
}
