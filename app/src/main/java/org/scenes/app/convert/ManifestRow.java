package org.scenes.app.convert;

import java.io.Serializable;
import java.util.List;

/**
 * One game of an archive's conversion, a row of its manifest.
 *
 * @param game the game's name: its game log's path in the archive without {@code .rcg[.gz]}, directories joined by '-'
 * @param path the game log's path in the archive
 * @param status converted, failed (see {@code reason}) or skipped (see {@code reason})
 * @param leftTeam the left team's name, empty when unknown
 * @param rightTeam the right team's name, empty when unknown
 * @param leftScore the left team's goals at the game's end, -1 when unknown
 * @param rightScore the right team's goals at the game's end, -1 when unknown
 * @param players scene files written
 * @param scenes scenes written
 * @param warnings what was wrong but left the scenes sound, each naming the file and line
 * @param commands where the players' commands came from: {@code rcl} (the command log), empty when not converted
 * @param reason why the game failed or was skipped, empty when converted
 */
public record ManifestRow(String game, String path, Status status, String leftTeam, String rightTeam, int leftScore,
                          int rightScore, int players, long scenes, List<String> warnings, String commands,
                          String reason) implements Serializable {
    /** What became of a game. */
    public enum Status { converted, failed, skipped }

    /** The manifest's columns, in the order of {@link #cells()}. */
    public static final List<String> COLUMNS = List.of("game", "path", "status", "left_team", "right_team",
            "left_score", "right_score", "players", "scenes", "warnings", "commands", "reason");

    public ManifestRow {
        warnings = List.copyOf(warnings);
    }

    static ManifestRow notConverted(String game, String path, Status status, String reason) {
        return new ManifestRow(game, path, status, "", "", -1, -1, 0, 0, List.of(), "", reason);
    }

    /** The CSV cells: the warnings counted (the game's own record in {@code .games/} holds their text). */
    List<Object> cells() {
        return List.of(game, path, status.name(), leftTeam, rightTeam, leftScore < 0 ? "" : leftScore,
                rightScore < 0 ? "" : rightScore, players, scenes, warnings.size(), commands, reason);
    }
}
