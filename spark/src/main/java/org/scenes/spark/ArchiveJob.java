package org.scenes.spark;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.Serializable;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import org.apache.hadoop.fs.FileStatus;
import org.apache.spark.api.java.JavaSparkContext;
import org.scenes.app.convert.ArchiveConversion;
import org.scenes.app.convert.ManifestRow;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.gamelog.ServerLogs;

/**
 * {@code scenes-spark convert ARCHIVE_DIR --out-dir OUT}: the archive mode of {@code scenes convert},
 * one task per game. A task runs the local command's step, {@link ArchiveConversion#convertGame},
 * into a scratch directory and publishes its files as {@code OUT/TEAM/GAME_UNUM.json.gz}, then the
 * game's record {@code OUT/.games/GAME.json}; the driver skips the games that have a record and
 * writes {@code OUT/manifest.csv} from the rows the tasks return (a few hundred bytes a game).
 */
final class ArchiveJob {
    private static final String[] COMMAND_LOG_SUFFIXES = {".rcl", ".rcl.gz"};

    private ArchiveJob() {
    }

    /** A game of the archive: its name, its path in the archive, its logs (the command log null when missing). */
    record Game(String name, String path, String gameLog, String commandLog) implements Serializable {
    }

    /** Whether the inputs are an archive: one directory with a game log ({@code .rcg[.gz]}) at any depth. */
    static boolean isArchive(HadoopFiles hadoop, List<String> inputs) throws IOException {
        return inputs.size() == 1 && hadoop.isDirectory(inputs.get(0))
                && !gameLogs(hadoop, inputs.get(0).replaceFirst("/+$", ""), "", null, new ArrayList<>(), true).isEmpty();
    }

    /** The archive's game logs in the order of their paths, as {@code scenes convert ARCHIVE_DIR} finds them. */
    static List<Game> games(HadoopFiles hadoop, String archive, String outDir) throws IOException {
        String root = archive.replaceFirst("/+$", "");
        List<Game> games = gameLogs(hadoop, root, "", hadoop.path(outDir).toString(), new ArrayList<>(), false);
        Map<String, String> names = new HashMap<>();
        for (Game game : games) {
            String before = names.put(game.name(), game.path());
            if (before != null) {
                throw new UsageException(before + " and " + game.path() + " in " + archive + " would both be game "
                        + game.name());
            }
        }
        if (games.isEmpty()) {
            throw new UsageException("no game logs (.rcg, .rcg.gz) under " + archive);
        }
        return games;
    }

    private static List<Game> gameLogs(HadoopFiles hadoop, String directory, String prefix, String outDir,
                                       List<Game> games, boolean firstOnly) throws IOException {
        for (FileStatus status : hadoop.list(directory)) {
            String name = status.getPath().getName();
            String full = directory + "/" + name;
            if (name.startsWith(".") || (outDir != null && status.getPath().toString().equals(outDir))) {
                continue;
            }
            if (status.isDirectory()) {
                gameLogs(hadoop, full, prefix + name + "/", outDir, games, firstOnly);
            } else if (ArchiveConversion.isGameLog(name)) {
                String path = prefix + name;
                games.add(new Game(ArchiveConversion.gameName(path), path, full, firstOnly ? null
                        : commandLogBeside(hadoop, directory, name)));
            }
            if (firstOnly && !games.isEmpty()) {
                return games;
            }
        }
        games.sort((a, b) -> a.path().compareTo(b.path()));
        return games;
    }

    private static String commandLogBeside(HadoopFiles hadoop, String directory, String gameLogName) throws IOException {
        String base = GameLogs.baseName(gameLogName);
        for (String suffix : COMMAND_LOG_SUFFIXES) {
            String candidate = directory + "/" + base + suffix;
            if (hadoop.exists(candidate) && hadoop.serverLogKind(candidate) == ServerLogs.Kind.COMMAND) {
                return candidate;
            }
        }
        return null;
    }

    static int run(ConvertCommand options, GameConversion.Settings settings, PrintWriter out, PrintWriter err)
            throws IOException {
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        String archive = options.inputs.get(0);
        String outDir = options.outDir.replaceFirst("/+$", "");
        List<Game> games = games(hadoop, archive, outDir);
        long started = System.nanoTime();
        Map<String, ManifestRow> rows = new HashMap<>();
        ArrayList<Game> todo = new ArrayList<>();
        for (Game game : games) {
            String record = outDir + "/" + ArchiveConversion.RECORDS + "/" + game.name() + ".json";
            ManifestRow row = hadoop.exists(record) ? ArchiveConversion.readRecord(hadoop.readAll(record)) : null;
            if (row != null && row.status() == ManifestRow.Status.converted) {
                rows.put(game.name(), row);
            } else {
                todo.add(game);
            }
        }
        int resumed = rows.size();
        if (!todo.isEmpty()) {
            try (JavaSparkContext spark = options.top.options.start("convert")) {
                for (ManifestRow row : spark.parallelize(todo, todo.size()).map(game -> convert(game, settings, outDir))
                        .collect()) {
                    rows.put(row.game(), row);
                }
            }
        }
        List<ManifestRow> manifest = games.stream().map(game -> rows.get(game.name())).toList();
        Path local = Files.createTempFile("scenes-spark-manifest", ".csv");
        try {
            Files.delete(local);
            ArchiveConversion.writeManifest(local, manifest);
            hadoop.publish(local, outDir + "/" + ArchiveConversion.MANIFEST);
        } finally {
            Files.deleteIfExists(local);
        }
        long failed = 0;
        for (ManifestRow row : manifest) {
            if (row.status() == ManifestRow.Status.failed) {
                failed++;
                err.printf("scenes-spark: error: %s: %s%n", row.path(), row.reason());
            } else if (row.status() == ManifestRow.Status.skipped) {
                err.printf("scenes-spark: warning: %s skipped: %s%n", row.path(), row.reason());
            }
        }
        long converted = manifest.stream().filter(r -> r.status() == ManifestRow.Status.converted).count();
        out.printf(Locale.ROOT, "%-22s %d in %s (one task each)%n", "Games", games.size(), archive);
        out.printf(Locale.ROOT, "%-22s %d (%d of them by an earlier run, not converted again)%n", "Converted",
                converted, resumed);
        out.printf(Locale.ROOT, "%-22s %d%n", "Failed", failed);
        out.printf(Locale.ROOT, "%-22s %d (no command log)%n", "Skipped",
                manifest.stream().filter(r -> r.status() == ManifestRow.Status.skipped).count());
        out.printf(Locale.ROOT, "%-22s %d scene files, %d scenes, in %s/TEAM/%s%n", "Written",
                manifest.stream().mapToLong(ManifestRow::players).sum(),
                manifest.stream().mapToLong(ManifestRow::scenes).sum(), outDir,
                settings.compression().fileName("GAME_UNUM"));
        out.printf(Locale.ROOT, "%-22s %s/%s%n", "Manifest", outDir, ArchiveConversion.MANIFEST);
        out.printf(Locale.ROOT, "%-22s %.2f s%n", "Time", (System.nanoTime() - started) / 1e9);
        out.flush();
        if (failed > 0) {
            err.printf("scenes-spark: error: %d of %d games failed (reasons above and in the manifest)%n", failed,
                    games.size());
        }
        err.flush();
        return failed > 0 ? 1 : 0;
    }

    /** A task: the game converted in a scratch directory, its files then its record published. */
    private static ManifestRow convert(Game game, GameConversion.Settings settings, String outDir) throws IOException {
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        Path scratch = Files.createTempDirectory("scenes-spark-archive");
        try {
            Path gameLog = hadoop.local(game.gameLog(), Files.createDirectory(scratch.resolve("logs")));
            Path commandLog = game.commandLog() == null ? null : hadoop.local(game.commandLog(), scratch.resolve("logs"));
            Path files = scratch.resolve("scenes");
            ManifestRow row = ArchiveConversion.convertGame(settings.convertSettings(), game.name(), game.path(),
                    gameLog, commandLog, files, () -> false);
            if (row.status() != ManifestRow.Status.converted) {
                return row;
            }
            try (Stream<Path> written = Files.walk(files)) {
                for (Path file : written.filter(Files::isRegularFile).sorted().toList()) {
                    hadoop.publish(file, outDir + "/" + files.relativize(file).toString().replace('\\', '/'));
                }
            }
            Path records = Files.createDirectory(scratch.resolve("records"));
            ArchiveConversion.writeRecord(records, row);
            hadoop.publish(records.resolve(game.name() + ".json"), outDir + "/" + ArchiveConversion.RECORDS + "/"
                    + game.name() + ".json");
            return row;
        } finally {
            try (Stream<Path> walk = Files.walk(scratch)) {
                for (Path file : walk.sorted(Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(file);
                }
            }
        }
    }
}
