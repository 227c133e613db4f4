package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.scenes.api.Grid;
import org.scenes.app.convert.ConvertSettings;
import org.scenes.app.convert.PlayerLogConversion;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.DropReason;
import org.scenes.internal.convert.MalformedLine;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.options.GameLogOptions;
import org.scenes.options.GridOptions;
import org.scenes.options.KeyConverters;
import org.scenes.options.PairingOptions;
import org.scenes.options.WorldOptions;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

/** {@code scenes convert}: player logs to scene files, with a summary of what was kept and dropped. */
@Command(name = "convert", mixinStandardHelpOptions = true,
        description = {"Convert player logs (.lsf, the scenes proxy's .log, timestamped captures; gzip or plain)"
                + " into scenes: each see with the actions sent after it (or, under synchronous vision, each cycle"
                + " with the latest see). Rules: docs/conversion.md.",
                "Or the server's logs of a game (GAME.rcg [GAME.rcl], told apart by content): scenes for every"
                        + " player, each see rebuilt with the server's vision model, paired with the player's commands.",
                "Or an archive: a directory tree of game logs (.rcg[.gz], the .rcl[.gz] beside), every player of every"
                        + " game into --out-dir DIR/TEAM/GAME_UNUM.json.gz with DIR/manifest.csv; games converted by an"
                        + " earlier run are skipped (docs/scale.md, archives)."})
final class ConvertCommand implements Callable<Integer> {
    /** Malformed-line warnings printed; the rest are only counted. */
    private static final int WARNINGS_SHOWN = 50;

    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Parameters(paramLabel = "LOG", arity = "1..*", description = "Player logs to convert, or a game's .rcg and .rcl, or an archive directory.")
    List<Path> logs;

    @ArgGroup(exclusive = true, multiplicity = "1")
    Output output;

    static final class Output {
        @Option(names = {"-o", "--output"}, paramLabel = "OUT.json[.gz|.zst]",
                description = "One scene file for all logs (gzip when the name ends in .gz, zstd in .zst).")
        Path file;

        @Option(names = "--out-dir", paramLabel = "DIR",
                description = "One scene file per log: DIR/<log name>.json.gz (game logs: DIR/TEAM_UNUM.json.gz;"
                        + " an archive: DIR/TEAM/GAME_UNUM.json.gz); .json.zst or .json with --compression.")
        Path directory;
    }

    @Option(names = "--compression", paramLabel = "gzip|zstd|none", defaultValue = "gzip",
            converter = KeyConverters.Compression.class,
            description = {"With --out-dir: how the scene files are compressed. zstd compresses in about a tenth of"
                    + " gzip's CPU (a game converts with a third less), files within 13 %% of gzip's size; every scenes"
                    + " command reads both (zstd -d and zcat too). Default: ${DEFAULT-VALUE}."})
    SceneCompression compression;

    @Mixin
    GridOptions gridOptions;

    @Mixin
    PairingOptions pairingOptions;

    @Mixin
    GameLogOptions gameLogOptions;

    @Mixin
    WorldOptions worldOptions;

    @Option(names = "--commands", paramLabel = "rcl|infer|auto", defaultValue = "auto",
            converter = KeyConverters.Commands.class,
            description = {"Game logs: where the players' commands come from: rcl (the command log, given or GAME.rcl"
                    + " beside the game log), infer (from the game log alone: the shows' command counters and"
                    + " rcssserver's turn, dash, kick and neck models; docs/conversion.md) or auto (the command log"
                    + " when there is one, else inferred; default)."})
    GameLogs.Commands commands;

    @Option(names = "--threads", paramLabel = "N", description = "Game logs: threads rebuilding the players."
            + " Default: the number of cores.")
    int threads = Runtime.getRuntime().availableProcessors();

    /** What becomes of a see the player left unanswered. */
    enum Unanswered { KEEP, DROP }

    @Option(names = "--unanswered", paramLabel = "keep|drop", defaultValue = "drop",
            converter = UnansweredConverter.class,
            description = {"A see the player left unanswered (no action before the next see): drop it (default, the"
                    + " classic rule) or keep it as a scene without action, so an imitator learns when its teacher"
                    + " waits (docs/conversion.md, unanswered sees)."})
    Unanswered unanswered;

    static final class UnansweredConverter implements ITypeConverter<Unanswered> {
        @Override
        public Unanswered convert(String value) {
            return switch (value) {
                case "keep" -> Unanswered.KEEP;
                case "drop" -> Unanswered.DROP;
                default -> throw new TypeConversionException("expected keep or drop, not '"
                        + value + "'");
            };
        }
    }

    private int warningsShown;

    /** The options as the convert services take them. */
    ConvertSettings settings(Grid grid) {
        gameLogOptions.check();
        return new ConvertSettings(grid, pairingOptions.pairing(), pairingOptions.strict(), worldOptions.world(),
                unanswered == Unanswered.KEEP, gameLogOptions.fading(), gameLogOptions.selected(),
                gameLogOptions.commandsFirst(), gameLogOptions.seePhase(), threads, compression);
    }

    @Override
    public Integer call() throws IOException {
        Grid grid = gridOptions.grid();
        Limits.threads("--threads", threads);
        if (ConvertArchive.isArchive(logs)) {
            return new ConvertArchive(this).run(grid);
        }
        if (output.file != null) {
            if (spec.commandLine().getParseResult().hasMatchedOption("--compression")) {
                throw new UsageException("--compression names the files of --out-dir; -o " + output.file
                        + " is compressed as its name ends (.gz gzip, .zst zstd)");
            }
            OutputPaths.checkFile("-o", output.file, logs);
        } else {
            OutputPaths.checkDirectory("--out-dir", output.directory);
            for (String name : outputNames(logs)) {
                OutputPaths.checkNotInput("--out-dir", output.directory.resolve(compression.fileName(name)), logs);
            }
        }
        PrintWriter err = spec.commandLine().getErr();
        GameLogConversion game = GameLogConversion.of(logs, commands);
        if (game != null) {
            return game.run(this, grid, spec.commandLine().getOut(), err);
        }
        PlayerLogConversion conversion = new PlayerLogConversion(new PlayerLogConversion.Request(logs, output.file,
                output.directory, settings(grid)));
        Thread interrupted = new Thread(() -> {
            // Ctrl-C or SIGTERM: no half-written scene file, and a word on what is complete
            List<Path> abandoned = AtomicOutput.abandonAll();
            List<Path> written = conversion.written();
            err.printf("%nscenes: interrupted: %d of %d scene files written%s%s%n", written.size(),
                    conversion.expected(), written.isEmpty() ? "" : " (" + written + ")",
                    abandoned.isEmpty() ? "" : "; not written (its temporary file removed): " + abandoned);
            err.flush();
        }, "scenes-convert-interrupted");
        if (!ShutdownHooks.addOrRun(interrupted)) {
            return ExitCodes.FAILURE;
        }
        PlayerLogConversion.Result result;
        try {
            result = conversion.run(new PlayerLogConversion.Listener() {
                @Override
                public void malformed(MalformedLine line) {
                    warn(err, line);
                }

                @Override
                public void logDone(Path log, ConversionReport report, boolean failed) {
                    tellNoScenes(err, log, report);
                }
            }, TerminalProgress.reporter(" MB", 1L << 20));
            if (warningsShown < result.total().malformed()) {
                err.printf("scenes: warning: %d more malformed lines not shown%n",
                        result.total().malformed() - warningsShown);
            }
            err.flush();
            // still under the hook: a signal while the summary prints is told what was written
            printSummary(spec.commandLine().getOut(), result.total(), grid, result.written(), result.seconds());
        } finally {
            ShutdownHooks.remove(interrupted);
        }
        if (!result.failed().isEmpty()) {
            err.printf("scenes: error: %d of %d logs gave no scenes%s%n", result.failed().size(), logs.size(),
                    output.file != null ? "; " + output.file + " not written" : "");
            err.flush();
            return ExitCodes.FAILURE;
        }
        return ExitCodes.OK;
    }

    /** An empty log, or a log with messages but no scene (a failed conversion), in one line naming the log. */
    private static void tellNoScenes(PrintWriter err, Path log, ConversionReport report) {
        if (report.lines() == 0) {
            err.printf("scenes: warning: %s is empty: no lines, no scenes%n", log);
            return;
        }
        if (!PlayerLogConversion.noScenes(report)) {
            return;
        }
        long commands = report.commands().values().stream().mapToLong(Long::longValue).sum();
        err.printf(Locale.ROOT, "scenes: error: %s: no scenes from %d lines (%d see, %d commands, %d malformed lines)%s%n",
                log, report.lines(), report.sees(), commands, report.malformed(),
                report.sees() == 0 ? ": no see at all; is this a player's log?"
                        : commands == 0 ? ": the player sent no command" : "");
    }

    private void warn(PrintWriter err, MalformedLine line) {
        if (warningsShown < WARNINGS_SHOWN) {
            err.println("scenes: warning: " + line.describe());
            warningsShown++;
        }
    }

    /** {@link PlayerLogConversion#outputNames}, two logs of one name being a usage error. */
    static List<String> outputNames(List<Path> logs) {
        try {
            return PlayerLogConversion.outputNames(logs);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--out-dir: " + e.getMessage() + "; convert them separately or with -o");
        }
    }

    private static void printSummary(PrintWriter out, ConversionReport report, Grid grid, List<Path> written,
                                     double seconds) {
        out.printf(Locale.ROOT, "%-22s %s%n", "Logs read", report.logs());
        out.printf(Locale.ROOT, "%-22s %s (%.1f MB of text)%n", "Lines read", report.lines(), report.bytes() / 1e6);
        out.printf(Locale.ROOT, "%-22s %s (%s repeated while paused, collapsed)%n", "See messages", report.sees(), report.repeatedSees());
        if (report.perCycleLogs() > 0) {
            out.printf(Locale.ROOT, "%-22s %s of %s logs (synchronous vision): %s cycles, %s of them on a standing clock;"
                            + " scenes by see age %s%n", "Scene per cycle", report.perCycleLogs(), report.logs(),
                    report.cycles(), report.repeatedSenseBodies(), report.seeAges().isEmpty() ? "none"
                            : report.seeAges().entrySet().stream().map(e -> e.getKey() + ": " + e.getValue())
                            .collect(Collectors.joining(", ")));
        }
        out.printf(Locale.ROOT, "%-22s %s  (grid %s)%n", "Scenes written", report.scenes(), grid.describe());
        out.printf(Locale.ROOT, "%-22s %s%n", "Scenes dropped", report.droppedTotal());
        for (DropReason reason : DropReason.values()) {
            out.printf(Locale.ROOT, "  %-20s %s%n", reason.label(), report.dropped(reason));
        }
        out.printf(Locale.ROOT, "%-22s %s%n", "Commands by type", counts(report.commands()));
        out.printf(Locale.ROOT, "%-22s %s%n", "Scene actions", counts(report.actions()));
        out.printf(Locale.ROOT, "%-22s %s (sent after a scene had its action; not kept)%n", "Extra actions", report.extraActions());
        out.printf(Locale.ROOT, "%-22s %s%n", "Ill-formed commands", report.illFormedCommands());
        out.printf(Locale.ROOT, "%-22s %s%n", "Unknown messages",
                report.unknown().isEmpty() ? "0" : report.unknown().entrySet().stream()
                        .map(e -> e.getKey() + " " + e.getValue()).collect(Collectors.joining(", ")));
        out.printf(Locale.ROOT, "%-22s %s%n", "Malformed lines", report.malformed());
        for (Path file : written) {
            out.printf(Locale.ROOT, "%-22s %s%n", "Written", file);
        }
        out.printf(Locale.ROOT, "%-22s %.2f s (%.1f MB/s of log text, scene files included)%n", "Time", seconds,
                seconds > 0 ? report.bytes() / 1e6 / seconds : 0);
        out.flush();
    }

    private static String counts(Map<? extends Enum<?>, Long> counts) {
        if (counts.isEmpty()) {
            return "none";
        }
        return counts.entrySet().stream()
                .map(e -> e.getKey().name().toLowerCase(Locale.ROOT) + " " + e.getValue())
                .collect(Collectors.joining(", "));
    }
}
