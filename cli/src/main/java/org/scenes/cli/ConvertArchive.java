package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.scenes.api.Grid;
import org.scenes.app.convert.ArchiveConversion;
import org.scenes.app.convert.ManifestRow;
import org.scenes.internal.files.AtomicOutput;

/**
 * {@code scenes convert ARCHIVE_DIR --out-dir DIR}: the options handed to the {@link ArchiveConversion}
 * service, a word on what was done when interrupted, and its summary printed.
 */
final class ConvertArchive {
    /** How long Ctrl-C waits for the game under way to give up its files (a game opens them in its first cycles). */
    private static final Duration STOP_WAIT = Duration.ofSeconds(2);

    private final ConvertCommand options;

    ConvertArchive(ConvertCommand options) {
        this.options = options;
    }

    /** Whether the inputs are an archive: one directory. */
    static boolean isArchive(List<Path> inputs) {
        return inputs.size() == 1 && ArchiveConversion.isArchive(inputs.get(0));
    }

    int run(Grid grid) throws IOException {
        Path archive = options.logs.get(0);
        Path outDir = options.output.directory;
        if (outDir == null) {
            throw new UsageException("-o: an archive (" + archive + " is a directory) is converted into --out-dir DIR:"
                    + " DIR/TEAM/GAME_UNUM.json.gz and DIR/" + ArchiveConversion.MANIFEST);
        }
        OutputPaths.checkDirectory("--out-dir", outDir);
        if (Files.exists(outDir) && Files.isSameFile(outDir, archive)) {
            throw new UsageException("--out-dir " + outDir + ": is the archive; name a directory of its own");
        }
        PrintWriter out = options.spec.commandLine().getOut();
        PrintWriter err = options.spec.commandLine().getErr();
        ArchiveConversion conversion = new ArchiveConversion(new ArchiveConversion.Request(archive, outDir,
                options.settings(grid), options.commands));
        Thread interrupted = new Thread(() -> {
            // Ctrl-C or SIGTERM: the game under way leaves no file and no record, so a new run converts it.
            // Stopped first, so that no output opens after its temporary files are removed
            conversion.cancel();
            List<Path> abandoned = new ArrayList<>(AtomicOutput.abandonAll());
            try {
                conversion.awaitStop(STOP_WAIT);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            abandoned.addAll(AtomicOutput.abandonAll());
            err.printf("%nscenes: interrupted: %d of %d games done; run the same command again to convert the rest%s%n",
                    conversion.done(), conversion.games(),
                    abandoned.isEmpty() ? "" : " (not written, temporary files removed: " + abandoned + ")");
            err.flush();
        }, "scenes-convert-interrupted");
        if (!ShutdownHooks.addOrRun(interrupted)) {
            return ExitCodes.FAILURE;
        }
        ArchiveConversion.Result result;
        try {
            result = conversion.run(TerminalProgress.reporter());
        } catch (IllegalArgumentException e) {
            // no game log in the directory, or two of one name: nothing was converted
            throw new UsageException(e.getMessage());
        } finally {
            ShutdownHooks.remove(interrupted);
        }
        for (ManifestRow row : result.rows()) {
            if (row.status() == ManifestRow.Status.failed) {
                err.printf("scenes: error: %s: %s%n", archive.resolve(row.path()), row.reason());
            } else if (row.status() == ManifestRow.Status.skipped) {
                err.printf("scenes: warning: %s skipped: %s%n", archive.resolve(row.path()), row.reason());
            }
        }
        err.flush();
        long converted = result.count(ManifestRow.Status.converted);
        long failed = result.count(ManifestRow.Status.failed);
        long skipped = result.count(ManifestRow.Status.skipped);
        long players = result.rows().stream().mapToLong(ManifestRow::players).sum();
        long scenes = result.rows().stream().mapToLong(ManifestRow::scenes).sum();
        long warnings = result.rows().stream().mapToLong(r -> r.warnings().size()).sum();
        out.printf(Locale.ROOT, "%-22s %d in %s%n", "Games", result.rows().size(), archive);
        out.printf(Locale.ROOT, "%-22s %d (%d of them by an earlier run, not converted again)%n", "Converted",
                converted, result.resumed());
        out.printf(Locale.ROOT, "%-22s %d%n", "Failed", failed);
        out.printf(Locale.ROOT, "%-22s %d (no command log)%n", "Skipped", skipped);
        out.printf(Locale.ROOT, "%-22s %d scene files, %d scenes, in %s/TEAM/%s%n", "Written",
                players, scenes, outDir, options.compression.fileName("GAME_UNUM"));
        out.printf(Locale.ROOT, "%-22s %d (each game's in the manifest and %s/.games/GAME.json)%n", "Warnings",
                warnings, outDir);
        out.printf(Locale.ROOT, "%-22s %s%n", "Manifest", result.manifest());
        out.printf(Locale.ROOT, "%-22s %.2f s%n", "Time", result.seconds());
        out.flush();
        if (failed > 0) {
            err.printf("scenes: error: %d of %d games failed (reasons above and in %s)%n", failed, result.rows().size(),
                    result.manifest());
            err.flush();
            return ExitCodes.FAILURE;
        }
        return ExitCodes.OK;
    }
}
