package org.scenes.fuzz;

import com.code_intelligence.jazzer.utils.Log;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.platform.launcher.LauncherSession;
import org.junit.platform.launcher.LauncherSessionListener;

/**
 * Keeps Jazzer's "INFO: Loaded N hooks" and "INFO: Instrumented class" lines (dozens per run of
 * the regression tests) off the console of {@code gradle test}; its warnings and errors still go to
 * standard error. Fuzzing ({@code JAZZER_FUZZ=1}) prints everything. Registered through
 * META-INF/services, so the JUnit launcher opens it before any fuzz test starts Jazzer.
 */
public final class QuietJazzerLog implements LauncherSessionListener {
    @Override
    public void launcherSessionOpened(LauncherSession session) {
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
