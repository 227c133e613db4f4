package org.scenes.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.apache.commons.csv.CSVPrinter;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionType;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.plugins.coverage.KeyScenes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/**
 * {@code scenes export}: one row per scene for other learners (Weka, scikit-learn): the nearest
 * ball, own and opponent goal, and the K nearest teammates and opponents as distance/direction
 * pairs, the number of unidentified players, optionally the previous action and the action's
 * parameters, and the primary action as the class label (last). Several files give one table,
 * their rows one after the other with a {@code file} column. Columns are a list built in one
 * place ({@link #columns()}) and filled in the same order ({@link #row}), so a new column is
 * one entry in each.
 */
@Command(name = "export", mixinStandardHelpOptions = true,
        description = {"Write one row per scene as CSV or ARFF: cycle, ball, own goal, opponent goal and the K nearest"
                + " teammates and opponents as distance/direction columns, unknown players, then the action label.",
                "Missing values: '?' in ARFF; in CSV the --missing text (default empty)."})
final class ExportCommand implements Callable<Integer> {
    enum Format { csv, arff }

    @Spec
    CommandSpec spec;

    @Option(names = "--format", required = true, paramLabel = "csv|arff", description = "Output format: ${COMPLETION-CANDIDATES}.")
    Format format;

    @Parameters(arity = "1..*", paramLabel = "FILE", description = "Scene files (.json or .json.gz): one table, a file column"
            + " first when there are several.")
    List<Path> files;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT", description = "Output file (written atomically); default stdout.")
    Path output;

    @Option(names = "--players", paramLabel = "K", defaultValue = "3",
            description = "Nearest teammates and opponents to export; default ${DEFAULT-VALUE}.")
    int players;

    enum Label { primary, body, neck, both }

    @Option(names = "--label", paramLabel = "primary|body|neck|both", defaultValue = "primary",
            description = {"The class column: the primary action's type (default), the body command class, the neck"
                    + " class or both (noop: a turn, dash, kick or turn_neck of 0; docs/validation.md)."})
    Label label;

    @Option(names = "--see-age", description = "Add a see_age column before the class: cycles since the see the scene shows.")
    boolean seeAge;

    @Option(names = "--parameters", description = "Add the primary action's parameters before the class: turn_moment,"
            + " dash_power, dash_dir, kick_power, kick_dir (missing unless the action is of that type).")
    boolean parameters;

    @Option(names = "--previous", description = "Add the previous scene's action (of the same file and player) before the"
            + " class: previous_action (type; none at the start) and previous_turn_moment.")
    boolean previous;

    @Option(names = "--key-scenes", paramLabel = "N", description = {"Only the N key scenes of each file (as 'show"
            + " --key-scenes' picks them, docs/extensions.md), in the file's order, with an influence column before the class."})
    Integer keyScenes;

    @Mixin
    KeySceneChoice keyChoice;

    @ParentCommand
    ScenesCommand top;

    @Option(names = "--missing", paramLabel = "TEXT", defaultValue = "",
            description = "CSV text for a value the scene lacks; default empty (ARFF always uses '?').")
    String missing;

    @Override
    public Integer call() throws IOException {
        if (players < 0) {
            throw new UsageException("--players must be 0 or more, not " + players);
        }
        if (keyScenes != null) {
            KeySceneChoice.check(keyScenes); // before any output
        }
        if (output != null) {
            OutputPaths.checkFile("-o", output, files);
        }
        if (output == null) {
            PrintWriter out = spec.commandLine().getOut();
            export(out);
            out.flush();
            return ExitCodes.OK;
        }
        try (AtomicOutput target = AtomicOutput.create(output)) {
            Writer writer = new BufferedWriter(new OutputStreamWriter(target.stream(), StandardCharsets.UTF_8), 1 << 16);
            long rows = export(writer);
            writer.flush();
            target.commit();
            spec.commandLine().getErr().printf("scenes: wrote %d rows to %s%n", rows, output);
        }
        return ExitCodes.OK;
    }

    private static final List<String> PARAMETER_COLUMNS = List.of("turn_moment", "dash_power", "dash_dir", "kick_power", "kick_dir");

    List<String> columns() {
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
        if (keyScenes != null) {
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

    private long export(Writer out) throws IOException {
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
                Map<Integer, Integer> keys = keyScenes == null ? null : keyScenes(file);
                Scene before = null;
                String name = file.getFileName().toString();
                for (int index = 0; reader.hasNext(); index++) {
                    Scene scene = reader.next();
                    boolean continues = before != null && before.observer().equals(scene.observer()) && before.cycle() <= scene.cycle();
                    Scene earlier = continues ? before : null;
                    before = scene;
                    if (keys != null && !keys.containsKey(index)) {
                        continue;
                    }
                    List<String> cells = row(name, scene, earlier, gap);
                    if (keys != null) {
                        cells.add(cells.size() - 1, Integer.toString(keys.get(index)));
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

    /** The key scenes of a file: index to influence. */
    private Map<Integer, Integer> keyScenes(Path file) {
        Map<Integer, Integer> keys = new HashMap<>();
        for (KeyScenes.Ranked ranked : keyChoice.choose(SceneFileReader.read(file), keyScenes, top.global.registry())) {
            keys.put(ranked.index(), ranked.influence());
        }
        return keys;
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
                    .sorted(Comparator.comparingDouble(ExportCommand::distanceOrFar)).toList();
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
