package org.scenes.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.app.export.Export;
import org.scenes.coverage.KeyScenes;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.scene.SceneFileReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/**
 * {@code scenes export}: one row per scene for other learners (Weka, scikit-learn); the table is
 * the app layer's {@link Export}, this command checks options and chooses where it goes.
 */
@Command(name = "export", mixinStandardHelpOptions = true,
        description = {"Write one row per scene as CSV or ARFF: cycle, ball, own goal, opponent goal and the K nearest"
                + " teammates and opponents as distance/direction columns, unknown players, then the action label.",
                "Missing values: '?' in ARFF; in CSV the --missing text (default empty)."})
final class ExportCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--format", required = true, paramLabel = "csv|arff", description = "Output format: ${COMPLETION-CANDIDATES}.")
    Export.Format format;

    @Parameters(arity = "1..*", paramLabel = "FILE", description = "Scene files (.json, .json.gz or .json.zst): one table, a file column"
            + " first when there are several.")
    List<Path> files;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT", description = "Output file (written atomically); default stdout.")
    Path output;

    @Option(names = "--players", paramLabel = "K", defaultValue = "3",
            description = "Nearest teammates and opponents to export; default ${DEFAULT-VALUE}.")
    int players;

    @Option(names = "--label", paramLabel = "primary|body|neck|both", defaultValue = "primary",
            description = {"The class column: the primary action's type (default), the body command class, the neck"
                    + " class or both (noop: a turn, dash, kick or turn_neck of 0; docs/validation.md)."})
    Export.Label label;

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
            table().write(out);
            out.flush();
            return ExitCodes.OK;
        }
        try (AtomicOutput target = AtomicOutput.create(output)) {
            Writer writer = new BufferedWriter(new OutputStreamWriter(target.stream(), StandardCharsets.UTF_8), 1 << 16);
            long rows = table().write(writer);
            writer.flush();
            target.commit();
            spec.commandLine().getErr().printf("scenes: wrote %d rows to %s%n", rows, output);
        }
        return ExitCodes.OK;
    }

    /** The table of these options; --key-scenes chooses each file's rows as show does. */
    private Export table() {
        return new Export(new Export.Request(files, format, players, label, seeAge, parameters, previous, missing),
                keyScenes == null ? null : file -> {
                    Map<Integer, Integer> keys = new HashMap<>();
                    for (KeyScenes.Ranked ranked : keyChoice.choose(SceneFileReader.read(file), keyScenes,
                            top.global.registry())) {
                        keys.put(ranked.index(), ranked.influence());
                    }
                    return keys;
                });
    }
}
