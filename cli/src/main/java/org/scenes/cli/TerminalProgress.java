package org.scenes.cli;

import java.util.function.LongConsumer;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.scenes.app.Progress;

/**
 * The one progress bar of the commands: drawn on standard error while a terminal (a console) is
 * attached, cleared when done; without a terminal (piped, redirected, in tests) it does nothing.
 */
final class TerminalProgress implements AutoCloseable {
    private static final TerminalProgress NONE = new TerminalProgress(null);

    private final ProgressBar bar;

    private TerminalProgress(ProgressBar bar) {
        this.bar = bar;
    }

    /** A bar of {@code max} steps named {@code task}. */
    static TerminalProgress start(String task, long max) {
        return start(task, max, "", 1);
    }

    /** A bar of {@code max} steps counted in {@code unit}s of {@code unitSize} steps ({@code " MB"}, 1 << 20). */
    static TerminalProgress start(String task, long max, String unit, long unitSize) {
        if (System.console() == null) {
            return NONE;
        }
        return new TerminalProgress(new ProgressBarBuilder().setTaskName(task).setInitialMax(max).setUnit(unit, unitSize)
                .setConsumer(new ConsoleProgressBarConsumer(System.err)).clearDisplayOnFinish().build());
    }

    /** No bar, terminal or not: for work too small or a {@code --quiet} run. */
    static TerminalProgress none() {
        return NONE;
    }

    /** The services' progress on this terminal: a bar from each begin to its end; nothing without a terminal. */
    static Progress reporter() {
        return reporter("", 1);
    }

    /** The same in {@code unit}s of {@code unitSize} steps ({@code " MB"}, 1 << 20). */
    static Progress reporter(String unit, long unitSize) {
        return new Progress() {
            private volatile TerminalProgress bar = none();

            @Override
            public void begin(String task, long total) {
                bar = total == 0 ? none() : start(task, total, unit, unitSize);
            }

            @Override
            public void step() {
                bar.step();
            }

            @Override
            public void stepBy(long steps) {
                bar.stepBy(steps);
            }

            @Override
            public void total(long total) {
                bar.maxHint(total);
            }

            @Override
            public void end() {
                bar.close();
                bar = none();
            }
        };
    }

    /** Whether a bar is drawn. */
    boolean shown() {
        return bar != null;
    }

    void step() {
        if (bar != null) {
            bar.step();
        }
    }

    void stepBy(long steps) {
        if (bar != null) {
            bar.stepBy(steps);
        }
    }

    void stepTo(long done) {
        if (bar != null) {
            bar.stepTo(done);
        }
    }

    /** Steps to the count given, for work that reports how far it is. */
    LongConsumer stepper() {
        return this::stepTo;
    }

    /** A new estimate of the total steps. */
    void maxHint(long max) {
        if (bar != null) {
            bar.maxHint(max);
        }
    }

    /** The text after the bar. */
    void message(String text) {
        if (bar != null) {
            bar.setExtraMessage(text);
        }
    }

    @Override
    public void close() {
        if (bar != null) {
            bar.close();
        }
    }
}
