package org.scenes.spark;

import java.io.IOException;
import java.io.Serializable;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import org.scenes.convert.ConversionReport;
import org.scenes.convert.DropReason;
import org.scenes.convert.Pairing;
import org.scenes.convert.SceneConverter;
import org.scenes.scene.Grid;
import org.scenes.scene.LazySceneFileWriter;

/**
 * One game's conversion, the unit of a {@code convert} job: each of the game's player logs goes
 * through the project's {@link SceneConverter} into a scene file, exactly as {@code scenes convert
 * --out-dir} writes it, which is then published under {@code OUT/GAME/}. Game logs ({@code .rcg},
 * one file per game holding every player) slot in here as another kind of input: one task, a scene
 * file per player.
 */
final class GameConversion {
    private GameConversion() {
    }

    /** A game: its name (the output directory) and its logs. */
    record Game(String name, ArrayList<String> logs) implements Serializable {
    }

    /** How logs become scenes: the grid, the pairing and strictness of {@code scenes convert}. */
    record Settings(int columns, double minAngle, double maxAngle, double[] bounds, String pairing, boolean strict)
            implements Serializable {
        static Settings of(Grid grid, Pairing pairing, boolean strict) {
            return new Settings(grid.columns(), grid.minAngle(), grid.maxAngle(), grid.bounds(), pairing.key(), strict);
        }

        Grid grid() {
            return new Grid(columns, minAngle, maxAngle, bounds);
        }
    }

    /** What converting one log gave: its counts, where its scenes went, or why it failed. */
    record LogResult(String log, String written, String error, long lines, long bytes, long sees, long scenes,
                     long repeatedSees, EnumMap<DropReason, Long> dropped, long malformed, ArrayList<String> warnings)
            implements Serializable {
    }

    /** Malformed-line warnings each log reports in full; the rest are counted. */
    static final int WARNINGS_KEPT = 10;

    static List<LogResult> convert(Game game, Settings settings, String outDir, List<String> names) throws IOException {
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        Grid grid = settings.grid();
        Path scratch = Files.createTempDirectory("scenes-spark-convert");
        List<LogResult> results = new ArrayList<>();
        try {
            for (int i = 0; i < game.logs().size(); i++) {
                String log = game.logs().get(i);
                ArrayList<String> warnings = new ArrayList<>();
                SceneConverter converter = new SceneConverter(grid, Pairing.fromKey(settings.pairing()), settings.strict(),
                        line -> {
                            if (warnings.size() < WARNINGS_KEPT) {
                                warnings.add(line.describe());
                            }
                        });
                Path local = hadoop.local(log, scratch);
                String fileName = log.substring(log.lastIndexOf('/') + 1);
                Path sceneFile = scratch.resolve(names.get(i) + ".json.gz");
                String target = outDir.replaceFirst("/+$", "") + "/" + game.name() + "/" + names.get(i) + ".json.gz";
                ConversionReport report;
                String error = null;
                try (LazySceneFileWriter writer = new LazySceneFileWriter(sceneFile, grid, fileName)) {
                    report = converter.convert(local, writer::write, bytes -> { });
                    error = noScenes(log, report);
                    if (error == null) {
                        writer.commit();
                    }
                } catch (IOException | RuntimeException e) {
                    results.add(new LogResult(log, null, log + ": " + e.getMessage(), 0, 0, 0, 0, 0,
                            new EnumMap<>(DropReason.class), 0, warnings));
                    cleanUp(local, sceneFile, scratch);
                    continue;
                }
                if (error == null) {
                    hadoop.publish(sceneFile, target);
                }
                EnumMap<DropReason, Long> dropped = new EnumMap<>(DropReason.class);
                for (DropReason reason : DropReason.values()) {
                    dropped.put(reason, report.dropped(reason));
                }
                results.add(new LogResult(log, error == null ? target : null, error, report.lines(), report.bytes(),
                        report.sees(), report.scenes(), report.repeatedSees(), dropped, report.malformed(), warnings));
                cleanUp(local, sceneFile, scratch);
            }
        } finally {
            try (var listing = Files.list(scratch)) {
                for (Path file : listing.toList()) {
                    Files.deleteIfExists(file);
                }
            }
            Files.deleteIfExists(scratch);
        }
        return results;
    }

    private static void cleanUp(Path local, Path sceneFile, Path scratch) throws IOException {
        if (local.startsWith(scratch)) {
            Files.deleteIfExists(local);
        }
        Files.deleteIfExists(sceneFile);
    }

    /** A log with messages but no scene failed, as for {@code scenes convert}; null when it did not. */
    private static String noScenes(String log, ConversionReport report) {
        if (report.scenes() > 0 || (report.messages() == 0 && report.malformed() == 0)) {
            return null;
        }
        long commands = report.commands().values().stream().mapToLong(Long::longValue).sum();
        return String.format(Locale.ROOT, "%s: no scenes from %d lines (%d see, %d commands, %d malformed lines)%s",
                log, report.lines(), report.sees(), commands, report.malformed(),
                report.sees() == 0 ? ": no see at all; is this a player's log?"
                        : commands == 0 ? ": the player sent no command" : "");
    }

    /**
     * One output name per log of a game: the log's name without extensions ({@code Carleton_1.lsf.gz}
     * gives {@code Carleton_1}), as {@code scenes convert --out-dir} names it.
     */
    static List<String> outputNames(Game game) {
        List<String> names = new ArrayList<>();
        for (String log : game.logs()) {
            String name = log.substring(log.lastIndexOf('/') + 1);
            for (String suffix : new String[] {".gz", ".lsf", ".log", ".txt"}) {
                if (name.endsWith(suffix) && name.length() > suffix.length()) {
                    name = name.substring(0, name.length() - suffix.length());
                }
            }
            if (names.contains(name)) {
                throw new UsageException("game " + game.name() + ": two logs would both be written to " + name + ".json.gz");
            }
            names.add(name);
        }
        return names;
    }
}
