package org.scenes.app.stats;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVRecord;
import org.scenes.api.ActionType;
import org.scenes.api.Scene;
import org.scenes.app.Progress;
import org.scenes.app.convert.ArchiveConversion;
import org.scenes.app.convert.ManifestRow;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.scene.SceneFileReader;

/**
 * {@code scenes stats DIR} over an archive's conversion ({@link ArchiveConversion}): per team, the
 * games the manifest lists as converted, won, drawn and lost, and the action mix of the scenes in
 * the team's directory ({@code DIR/TEAM/*.json.gz} or {@code .json.zst}, each scene's primary action).
 */
public final class ArchiveStats {
    private ArchiveStats() {
    }

    /**
     * One team.
     *
     * @param games converted games the team played
     * @param files the team's scene files
     * @param actions scenes per primary action type
     */
    public record Team(String name, int games, int wins, int draws, int losses, int files, long scenes,
                       Map<ActionType, Long> actions) {
        public Team {
            actions = Map.copyOf(actions);
        }
    }

    /** Whether {@code directory} holds an archive's conversion: its manifest. */
    public static boolean isArchiveOutput(Path directory) {
        return Files.isRegularFile(directory.resolve(ArchiveConversion.MANIFEST));
    }

    /** The teams in name order; progress in scene files read. */
    public static List<Team> of(Path directory, Progress progress) throws IOException {
        Map<String, int[]> results = new TreeMap<>();
        Path manifest = directory.resolve(ArchiveConversion.MANIFEST);
        try (Reader in = Files.newBufferedReader(manifest)) {
            for (CSVRecord row : CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).build().parse(in)) {
                if (!row.get("status").equals(ManifestRow.Status.converted.name())) {
                    continue;
                }
                String left = row.get("left_team");
                String right = row.get("right_team");
                int leftScore = Integer.parseInt(row.get("left_score"));
                int rightScore = Integer.parseInt(row.get("right_score"));
                count(results, left, Integer.compare(leftScore, rightScore));
                count(results, right, Integer.compare(rightScore, leftScore));
            }
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new IOException(manifest + ": not a manifest of scenes convert: " + e.getMessage(), e);
        }
        Map<String, List<Path>> files = new TreeMap<>();
        for (String team : results.keySet()) {
            Path teamDirectory = directory.resolve(team);
            if (!Files.isDirectory(teamDirectory)) {
                files.put(team, List.of());
                continue;
            }
            files.put(team, SceneCompression.sceneFilesIn(teamDirectory));
        }
        progress.begin("Reading", files.values().stream().mapToLong(List::size).sum());
        List<Team> teams = new ArrayList<>();
        try {
            for (Map.Entry<String, int[]> team : results.entrySet()) {
                Map<ActionType, Long> actions = new EnumMap<>(ActionType.class);
                long scenes = 0;
                for (Path file : files.get(team.getKey())) {
                    try (SceneFileReader reader = SceneFileReader.open(file)) {
                        while (reader.hasNext()) {
                            Scene scene = reader.next();
                            scenes++;
                            actions.merge(scene.actionType(), 1L, Long::sum);
                        }
                    }
                    progress.step();
                }
                int[] r = team.getValue();
                teams.add(new Team(team.getKey(), r[0] + r[1] + r[2], r[0], r[1], r[2], files.get(team.getKey()).size(),
                        scenes, actions));
            }
        } finally {
            progress.end();
        }
        return teams;
    }

    /** A game of the team: won (1), drawn (0) or lost (-1). */
    private static void count(Map<String, int[]> results, String team, int outcome) {
        if (!team.isEmpty()) {
            results.computeIfAbsent(team, t -> new int[3])[outcome > 0 ? 0 : outcome == 0 ? 1 : 2]++;
        }
    }
}
