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
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import org.scenes.files.AtomicOutput;
import org.scenes.scene.ActionType;
import org.scenes.scene.ObjectKind;
import org.scenes.scene.Relation;
import org.scenes.scene.Scene;
import org.scenes.scene.SceneFileReader;
import org.scenes.scene.SeenObject;
import org.scenes.validate.ActionLabel;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code scenes export}: one row per scene for other learners (Weka, scikit-learn): the nearest
 * ball, own and opponent goal, and the K nearest teammates and opponents as distance/direction
 * pairs, the number of unidentified players, and the primary action as the class label (last).
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

    @Parameters(paramLabel = "FILE", description = "A scene file (.json or .json.gz).")
    Path file;

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

    @Option(names = "--missing", paramLabel = "TEXT", defaultValue = "",
            description = "CSV text for a value the scene lacks; default empty (ARFF always uses '?').")
    String missing;

    @Override
    public Integer call() throws IOException {
        if (players < 0) {
            throw new UsageException("--players must be 0 or more, not " + players);
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

    List<String> columns() {
        List<String> columns = new ArrayList<>(List.of("cycle", "ball_dist", "ball_dir", "own_goal_dist", "own_goal_dir",
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
        columns.add(label == Label.primary ? "action" : label.name());
        return columns;
    }

    private long export(Writer out) throws IOException {
        List<String> columns = columns();
        String gap = format == Format.arff ? "?" : missing;
        try (SceneFileReader reader = SceneFileReader.open(file)) {
            if (format == Format.arff) {
                out.write("% scenes export of " + file.getFileName() + " (grid " + reader.header().grid().describe() + ")\n");
                out.write("@relation scenes\n\n");
                for (String column : columns.subList(0, columns.size() - 1)) {
                    out.write("@attribute " + column + " numeric\n");
                }
                out.write("@attribute " + columns.get(columns.size() - 1) + " {" + String.join(",", classValues())
                        + "}\n\n@data\n");
            } else {
                out.write(String.join(",", columns) + "\n");
            }
            long rows = 0;
            StringBuilder row = new StringBuilder(256);
            while (reader.hasNext()) {
                row.setLength(0);
                appendRow(row, reader.next(), gap);
                out.write(row.append('\n').toString());
                rows++;
            }
            return rows;
        }
    }

    private void appendRow(StringBuilder row, Scene scene, String gap) {
        row.append(scene.cycle());
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
        row.append(',').append(objects.stream()
                .filter(o -> o.kind() == ObjectKind.PLAYER && o.relation() == Relation.UNKNOWN).count());
        if (seeAge) {
            row.append(',').append(scene.seeAge());
        }
        row.append(',').append(label == Label.primary ? scene.actionType().key() : actionLabel().of(scene.actions()));
    }

    private ActionLabel actionLabel() {
        return switch (label) {
            case primary -> ActionLabel.PRIMARY;
            case body -> ActionLabel.BODY;
            case neck -> ActionLabel.NECK;
            case both -> ActionLabel.BOTH;
        };
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

    private static void pair(StringBuilder row, SeenObject object, String gap) {
        row.append(',');
        number(row, object == null ? Double.NaN : object.distance(), gap);
        row.append(',');
        number(row, object == null ? Double.NaN : object.direction(), gap);
    }

    private static void number(StringBuilder row, double value, String gap) {
        if (Double.isNaN(value)) {
            row.append(gap);
        } else if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            row.append((long) value);
        } else {
            row.append(value);
        }
    }
}
