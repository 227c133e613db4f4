package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.coverage.KeyScenes;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.scene.VisionTable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes show}: scenes as visiontables. */
@Command(name = "show", mixinStandardHelpOptions = true,
        description = "Print scenes of a scene file as visiontables (all of them, or one by index or cycle).")
final class ShowCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "FILE", description = "A scene file (.json, .json.gz or .json.zst).")
    Path file;

    @ArgGroup(exclusive = true)
    Selection selection;

    static final class Selection {
        @Option(names = "--index", paramLabel = "N", description = "Only the N-th scene, counting from 0.")
        Long index;

        @Option(names = "--cycle", paramLabel = "C", description = "Only the scenes of server cycle C.")
        Integer cycle;

        @Option(names = "--key-scenes", paramLabel = "N",
                description = "The N scenes whose neighbours' predictions hang on them most (see docs/extensions.md), most first.")
        Integer keyScenes;
    }

    @ParentCommand
    ScenesCommand top;

    @Mixin
    KeySceneChoice keyScenes;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        if (selection != null && selection.keyScenes != null) {
            return showKeyScenes(out, selection.keyScenes);
        }
        long shown = 0;
        long index = 0;
        try (SceneFileReader reader = SceneFileReader.open(file)) {
            Grid grid = reader.header().grid();
            while (reader.hasNext()) {
                Scene scene = reader.next();
                // with --index the rest is still read: a truncated or broken file is an error, not silence
                boolean wanted = selection == null
                        || (selection.index != null && selection.index == index)
                        || (selection.cycle != null && selection.cycle == scene.cycle());
                if (wanted) {
                    out.printf("#%d  ", index);
                    out.print(VisionTable.render(scene, grid));
                    out.println();
                    shown++;
                }
                index++;
            }
        }
        out.flush();
        if (shown == 0 && selection != null) {
            String what = selection.index != null ? "index " + selection.index : "cycle " + selection.cycle;
            throw new UsageException("no scene with " + what + " in " + file + " (" + index + " scenes)");
        }
        return ExitCodes.OK;
    }

    private int showKeyScenes(PrintWriter out, int count) {
        SceneFile scenes = SceneFileReader.read(file);
        return print(out, keyScenes.choose(scenes, count, top.global.registry()), scenes.grid(), keyScenes.keyBy.key());
    }

    private static int print(PrintWriter out, List<KeyScenes.Ranked> ranked, Grid grid, String measure) {
        for (KeyScenes.Ranked each : ranked) {
            out.printf("#%d  %s %d  ", each.index(), measure, each.influence());
            out.print(VisionTable.render(each.scene(), grid));
            out.println();
        }
        out.flush();
        return ExitCodes.OK;
    }
}
