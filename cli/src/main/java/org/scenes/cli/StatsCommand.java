package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionType;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.app.convert.ArchiveConversion;
import org.scenes.app.stats.ArchiveStats;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code scenes stats}: what a scene file holds, counted per action and object kind. */
@Command(name = "stats", mixinStandardHelpOptions = true,
        description = {"Count the scenes of a scene file per action, and their objects per kind and relation.",
                "Over an archive's conversion (the --out-dir of scenes convert ARCHIVE_DIR): games per team and the"
                        + " action mix of each team's scenes."})
final class StatsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "FILE", description = "A scene file (.json, .json.gz or .json.zst), or the directory of an"
            + " archive's conversion.")
    Path file;

    @Override
    public Integer call() throws IOException {
        if (Files.isDirectory(file)) {
            if (!ArchiveStats.isArchiveOutput(file)) {
                throw new UsageException(file + ": a directory without " + ArchiveConversion.MANIFEST + "; give a scene"
                        + " file, or the --out-dir of scenes convert ARCHIVE_DIR");
            }
            return archive();
        }
        long scenes = 0;
        long objects = 0;
        int firstCycle = Integer.MAX_VALUE;
        int lastCycle = Integer.MIN_VALUE;
        Map<ActionType, Long> primary = new EnumMap<>(ActionType.class);
        Map<ActionType, Long> secondary = new EnumMap<>(ActionType.class);
        Map<ObjectKind, Long> kinds = new EnumMap<>(ObjectKind.class);
        Map<String, Long> relations = new TreeMap<>();
        Map<String, Long> observers = new TreeMap<>();
        Map<String, Long> bodyClasses = new TreeMap<>();
        Map<String, Long> neckClasses = new TreeMap<>();
        Map<Integer, Long> seeAges = new TreeMap<>();
        SceneFileHeader header;
        try (SceneFileReader reader = SceneFileReader.open(file)) {
            header = reader.header();
            while (reader.hasNext()) {
                Scene scene = reader.next();
                scenes++;
                firstCycle = Math.min(firstCycle, scene.cycle());
                lastCycle = Math.max(lastCycle, scene.cycle());
                observers.merge(scene.observer().label(), 1L, Long::sum);
                primary.merge(scene.actionType(), 1L, Long::sum);
                bodyClasses.merge(ActionLabel.BODY.of(scene.actions()), 1L, Long::sum);
                neckClasses.merge(ActionLabel.NECK.of(scene.actions()), 1L, Long::sum);
                seeAges.merge(scene.seeAge(), 1L, Long::sum);
                for (Action action : scene.actions().subList(Math.min(1, scene.actions().size()), scene.actions().size())) {
                    secondary.merge(action.type(), 1L, Long::sum);
                }
                for (SeenObject object : scene.objects()) {
                    objects++;
                    kinds.merge(object.kind(), 1L, Long::sum);
                    if (object.relation() != Relation.NONE) {
                        relations.merge(object.kind().key() + " " + object.relation().key(), 1L, Long::sum);
                    }
                }
            }
        }
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%-24s %s%n", "File", file);
        out.printf(Locale.ROOT, "%-24s %s%n", "Grid", header.grid().describe());
        out.printf(Locale.ROOT, "%-24s %s%n", "Source log", header.source().log().isEmpty() ? "-" : header.source().log());
        out.printf(Locale.ROOT, "%-24s %d%n", "Scenes", scenes);
        if (scenes > 0) {
            out.printf(Locale.ROOT, "%-24s %d .. %d%n", "Cycles", firstCycle, lastCycle);
        }
        out.println();
        out.println("Observers");
        observers.forEach((label, count) -> out.printf(Locale.ROOT, "  %-22s %8d%n", label, count));
        out.println();
        out.printf(Locale.ROOT, "%-24s %8s %8s %8s%n", "Action", "primary", "%", "second");
        for (ActionType type : ActionType.values()) {
            long count = primary.getOrDefault(type, 0L);
            long second = secondary.getOrDefault(type, 0L);
            if (count > 0 || second > 0) {
                out.printf(Locale.ROOT, "  %-22s %8d %8.1f %8d%n", type.key(), count, scenes == 0 ? 0 : 100.0 * count / scenes, second);
            }
        }
        out.printf(Locale.ROOT, "%-24s %s%n", "Body classes", classes(bodyClasses));
        out.printf(Locale.ROOT, "%-24s %s%n", "Neck classes", classes(neckClasses));
        out.printf(Locale.ROOT, "%-24s %s%n", "See age (cycles)", classes(seeAges));
        out.println();
        out.printf(Locale.ROOT, "%-24s %8s %8s%n", "Object kind", "count", "/scene");
        for (ObjectKind kind : ObjectKind.values()) {
            long count = kinds.getOrDefault(kind, 0L);
            out.printf(Locale.ROOT, "  %-22s %8d %8.2f%n", kind.key(), count, scenes == 0 ? 0 : (double) count / scenes);
        }
        out.printf(Locale.ROOT, "  %-22s %8d %8.2f%n", "all", objects, scenes == 0 ? 0 : (double) objects / scenes);
        out.println();
        out.printf(Locale.ROOT, "%-24s %8s%n", "Relation", "count");
        relations.forEach((relation, count) -> out.printf(Locale.ROOT, "  %-22s %8d%n", relation, count));
        out.flush();
        return ExitCodes.OK;
    }

    /** Per team: its games and the share of each primary action in its scenes. */
    private int archive() throws IOException {
        List<ArchiveStats.Team> teams = ArchiveStats.of(file, TerminalProgress.reporter());
        List<ActionType> types = Arrays.stream(ActionType.values())
                .filter(type -> teams.stream().anyMatch(team -> team.actions().containsKey(type))).toList();
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%-24s %s (%d teams)%n", "Archive", file, teams.size());
        out.println();
        out.printf(Locale.ROOT, "%-20s %6s %5s %5s %5s %6s %10s", "Team", "games", "won", "drawn", "lost", "files",
                "scenes");
        for (ActionType type : types) {
            out.printf(Locale.ROOT, " %8s", type.key() + " %");
        }
        out.println();
        for (ArchiveStats.Team team : teams) {
            out.printf(Locale.ROOT, "%-20s %6d %5d %5d %5d %6d %10d", team.name(), team.games(), team.wins(),
                    team.draws(), team.losses(), team.files(), team.scenes());
            for (ActionType type : types) {
                long count = team.actions().getOrDefault(type, 0L);
                out.printf(Locale.ROOT, " %8.1f", team.scenes() == 0 ? 0 : 100.0 * count / team.scenes());
            }
            out.println();
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** {@code noop 120, dash 80}: most common first. */
    private static <K> String classes(Map<K, Long> counts) {
        return counts.isEmpty() ? "none" : counts.entrySet().stream()
                .sorted(Map.Entry.<K, Long>comparingByValue().reversed())
                .map(e -> e.getKey() + " " + e.getValue()).collect(Collectors.joining(", "));
    }
}
