package org.scenes.app.export;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.apache.commons.csv.CSVPrinter;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionType;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.scene.SceneFileReader;

/**
 * {@code scenes export}: one row per scene for other learners (Weka, scikit-learn): the nearest
 * ball, own and opponent goal, and the K nearest teammates and opponents as distance/direction
 * pairs, the number of unidentified players, optionally the previous action and the action's
 * parameters, and the primary action as the class label (last). Several files give one table,
 * their rows one after the other with a {@code file} column. Columns are a list built in one
 * place ({@link #columns()}) and filled in the same order ({@link #row}), so a new column is
 * one entry in each.
 */
public final class Export {
    /** The table's format. */
    public enum Format { csv, arff }

    /** The class column: the primary action's type, the body command class, the neck class or both. */
    public enum Label { primary, body, neck, both }

    /**
     * What to export.
     *
     * @param files the scene files, one table
     * @param format CSV or ARFF
     * @param players nearest teammates and opponents
     * @param label the class column
     * @param seeAge add a see_age column
     * @param parameters add the primary action's parameters
     * @param previous add the previous scene's action
     * @param missing CSV text for a missing value (ARFF always uses '?')
     */
    public record Request(List<Path> files, Format format, int players, Label label, boolean seeAge, boolean parameters,
                          boolean previous, String missing) {
        public Request {
            files = List.copyOf(files);
            if (players < 0) {
                throw new IllegalArgumentException("players must be 0 or more, not " + players);
            }
        }
    }

    private final List<Path> files;
    private final Format format;
    private final int players;
    private final Label label;
    private final boolean seeAge;
    private final boolean parameters;
    private final boolean previous;
    private final String missing;
    private final Function<Path, Map<Integer, Integer>> keys;

    /**
     * @param keys a file's key scenes (index to influence), whose rows alone are written with an
     *     influence column; null for every scene
     */
    public Export(Request request, Function<Path, Map<Integer, Integer>> keys) {
        this.files = request.files();
        this.format = request.format();
        this.players = request.players();
        this.label = request.label();
        this.seeAge = request.seeAge();
        this.parameters = request.parameters();
        this.previous = request.previous();
        this.missing = request.missing();
        this.keys = keys;
    }

    private static final List<String> PARAMETER_COLUMNS = List.of("turn_moment", "dash_power", "dash_dir", "kick_power", "kick_dir");

    /** The columns, in order: built in one place and filled in the same order by {@link #row}. */
    public List<String> columns() {
        List<String> columns = new ArrayList<>();
        if (files.size() > 1) {
            columns.add("file");
        }
        columns.addAll(List.of("cycle", "ball_dist", "ball_dir", "own_goal_dist", "own_goal_dir",
                "opp_goal_dist", "opp_goal_dir"));
        for (String who : new String[] {"mate", "opp"}) {
            for (int i = 1; i <= players; i++) {
                columns.add(who + i + "_dist");
                columns.add(who + i + "_dir");
            }
        }
        columns.add("unknown_players");
        if (seeAge) {
            columns.add("see_age");
        }
        if (previous) {
            columns.add("previous_action");
            columns.add("previous_turn_moment");
        }
        if (parameters) {
            columns.addAll(PARAMETER_COLUMNS);
        }
        if (keys != null) {
            columns.add("influence");
        }
        columns.add(label == Label.primary ? "action" : label.name());
        return columns;
    }

    /** ARFF types of the columns that are not numeric; the class is nominal too. */
    private String arffType(String column) {
        return switch (column) {
            case "file" -> "string";
            case "previous_action" -> "{" + String.join(",", primaryValues()) + "}";
            default -> "numeric";
        };
    }

    /**
     * Writes the table: the ARFF header or the CSV header, then one row per scene (per key scene).
     *
     * @return the rows written
     */
    public long write(Writer out) throws IOException {
        List<String> columns = columns();
        String gap = format == Format.arff ? "?" : missing;
        CSVPrinter csv = null;
        long rows = 0;
        for (Path file : files) {
            try (SceneFileReader reader = SceneFileReader.open(file)) {
                if (rows == 0 && file == files.get(0)) {
                    if (format == Format.arff) {
                        out.write("% scenes export of " + files.stream().map(f -> f.getFileName().toString())
                                .collect(Collectors.joining(", ")) + " (grid " + reader.header().grid().describe() + ")\n");
                        out.write("@relation scenes\n\n");
                        for (String column : columns.subList(0, columns.size() - 1)) {
                            out.write("@attribute " + column + " " + arffType(column) + "\n");
                        }
                        out.write("@attribute " + columns.get(columns.size() - 1) + " {" + String.join(",", classValues())
                                + "}\n\n@data\n");
                    } else {
                        csv = CsvTables.printer(out, columns);
                    }
                }
                Map<Integer, Integer> chosen = keys == null ? null : keys.apply(file);
                Scene before = null;
                String name = file.getFileName().toString();
                for (int index = 0; reader.hasNext(); index++) {
                    Scene scene = reader.next();
                    boolean continues = before != null && before.observer().equals(scene.observer()) && before.cycle() <= scene.cycle();
                    Scene earlier = continues ? before : null;
                    before = scene;
                    if (chosen != null && !chosen.containsKey(index)) {
                        continue;
                    }
                    List<String> cells = row(name, scene, earlier, gap);
                    if (chosen != null) {
                        cells.add(cells.size() - 1, Integer.toString(chosen.get(index)));
                    }
                    if (csv != null) {
                        csv.printRecord(cells);
                    } else {
                        out.write(arffRow(cells));
                    }
                    rows++;
                }
            }
        }
        if (csv != null) {
            csv.flush();
        }
        return rows;
    }

    /** ARFF quotes strings with a comma, quote or space in single quotes. */
    private static String arffRow(List<String> cells) {
        StringBuilder line = new StringBuilder(256);
        for (String cell : cells) {
            if (line.length() > 0) {
                line.append(',');
            }
            if (cell.matches(".*[,'\\s%{}].*")) {
                line.append('\'').append(cell.replace("\\", "\\\\").replace("'", "\\'")).append('\'');
            } else {
                line.append(cell);
            }
        }
        return line.append('\n').toString();
    }

    /** One scene's cells, in the order of {@link #columns()}. */
    private List<String> row(String file, Scene scene, Scene earlier, String gap) {
        List<String> row = new ArrayList<>(32);
        if (files.size() > 1) {
            row.add(file);
        }
        row.add(Integer.toString(scene.cycle()));
        List<SeenObject> objects = scene.objects();
        pair(row, nearest(objects, ObjectKind.BALL, null), gap);
        pair(row, nearest(objects, ObjectKind.GOAL, Relation.OWN), gap);
        pair(row, nearest(objects, ObjectKind.GOAL, Relation.OPPONENT), gap);
        for (Relation relation : new Relation[] {Relation.TEAMMATE, Relation.OPPONENT}) {
            List<SeenObject> sorted = objects.stream()
                    .filter(o -> o.kind() == ObjectKind.PLAYER && o.relation() == relation)
                    .sorted(Comparator.comparingDouble(Export::distanceOrFar)).toList();
            for (int i = 0; i < players; i++) {
                pair(row, i < sorted.size() ? sorted.get(i) : null, gap);
            }
        }
        row.add(Long.toString(objects.stream()
                .filter(o -> o.kind() == ObjectKind.PLAYER && o.relation() == Relation.UNKNOWN).count()));
        if (seeAge) {
            row.add(Integer.toString(scene.seeAge()));
        }
        if (previous) {
            Action last = earlier == null ? null : earlier.primaryAction();
            row.add(last == null ? ActionType.NONE.key() : last.type().key());
            row.add(number(last != null && last.type() == ActionType.TURN ? last.first() : Double.NaN, gap));
        }
        if (parameters) {
            Action action = scene.primaryAction();
            ActionType type = action == null ? ActionType.NONE : action.type();
            row.add(number(type == ActionType.TURN ? action.first() : Double.NaN, gap));
            row.add(number(type == ActionType.DASH ? action.first() : Double.NaN, gap));
            row.add(number(type == ActionType.DASH ? action.second() : Double.NaN, gap));
            row.add(number(type == ActionType.KICK ? action.first() : Double.NaN, gap));
            row.add(number(type == ActionType.KICK ? action.second() : Double.NaN, gap));
        }
        row.add(label == Label.primary ? scene.actionType().key() : actionLabel().of(scene.actions()));
        return row;
    }

    private ActionLabel actionLabel() {
        return switch (label) {
            case primary -> ActionLabel.PRIMARY;
            case body -> ActionLabel.BODY;
            case neck -> ActionLabel.NECK;
            case both -> ActionLabel.BOTH;
        };
    }

    /** Every action type, none included: the values of previous_action. */
    private static List<String> primaryValues() {
        return Arrays.stream(ActionType.values()).map(ActionType::key).toList();
    }

    /** The ARFF class values: every class the label can take. */
    private List<String> classValues() {
        List<String> body = new ArrayList<>(List.of(ActionLabel.NONE, ActionLabel.NO_OP));
        Arrays.stream(ActionType.values()).filter(ActionType::worldChanging).forEach(t -> body.add(t.key()));
        List<String> neck = List.of(ActionLabel.NONE, ActionLabel.NO_OP, ActionType.TURN_NECK.key());
        return switch (label) {
            case primary -> Arrays.stream(ActionType.values()).filter(t -> t != ActionType.NONE).map(ActionType::key).toList();
            case body -> body;
            case neck -> neck;
            case both -> body.stream().flatMap(b -> neck.stream().map(n -> b + "+" + n)).toList();
        };
    }

    private static SeenObject nearest(List<SeenObject> objects, ObjectKind kind, Relation relation) {
        SeenObject best = null;
        for (SeenObject object : objects) {
            if (object.kind() == kind && (relation == null || object.relation() == relation)
                    && (best == null || distanceOrFar(object) < distanceOrFar(best))) {
                best = object;
            }
        }
        return best;
    }

    private static double distanceOrFar(SeenObject object) {
        return Double.isNaN(object.distance()) ? Double.MAX_VALUE : object.distance();
    }

    private static void pair(List<String> row, SeenObject object, String gap) {
        row.add(number(object == null ? Double.NaN : object.distance(), gap));
        row.add(number(object == null ? Double.NaN : object.direction(), gap));
    }

    private static String number(double value, String gap) {
        if (Double.isNaN(value)) {
            return gap;
        } else if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Double.toString(value);
    }
}
