package org.scenes.app.condense;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.scenes.api.Grid;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.coverage.Condenser;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.internal.validate.MatchConfig;

/**
 * {@code scenes condense}: a smaller knowledge base that predicts the dropped scenes as the whole
 * one did: edited (Wilson) then condensed (Hart) nearest neighbour with the configuration's metric,
 * written as one scene file.
 */
public final class Condensation {
    private Condensation() {
    }

    /**
     * What to condense.
     *
     * @param train the scene files, on one grid
     * @param config the configuration whose metric and transforms decide
     * @param editK neighbours whose majority must agree with a scene for editing to keep it; 0: no editing
     * @param output the condensed scene file, written atomically
     */
    public record Request(List<Path> train, MatchConfig config, int editK, Path output) {
        public Request {
            train = List.copyOf(train);
            if (editK < 0) {
                throw new IllegalArgumentException("editK must be 0 or more, not " + editK);
            }
        }
    }

    /**
     * What was kept.
     *
     * @param scenes the scenes a knowledge base of the files would store
     * @param edited the scenes editing removed
     * @param kept the scenes written
     * @param passes the condensing passes
     * @param seconds the time editing and condensing took
     */
    public record Result(int scenes, int edited, int kept, int passes, double seconds) {
    }

    /** Condenses and writes the request's output. */
    public static Result run(Request request, PluginRegistry registry) throws IOException {
        MatchConfig config = request.config();
        config.check(registry);
        List<Scene> scenes = new ArrayList<>();
        List<SceneFile> files = request.train().stream().map(SceneFileReader::read).toList();
        Grid grid = Grid.common(request.train(), files.stream().map(SceneFile::grid).toList());
        for (SceneFile file : files) {
            // what a knowledge base of these files would store (transforms such as mirror add scenes)
            scenes.addAll(KnowledgeBase.stored(file.scenes(), config.transformFactory(registry).get()));
        }
        long start = System.nanoTime();
        Condenser.Result result = new Condenser(config.metricFactory(registry), request.editK()).condense(grid, scenes);
        double seconds = (System.nanoTime() - start) / 1e9;
        try (SceneFileWriter writer = SceneFileWriter.create(request.output(),
                SceneFileHeader.of(grid, new SceneSource("condensed", null)))) {
            for (Scene scene : result.scenes()) {
                // remembered objects and memory are rebuilt by transforms when the file is read
                writer.write(scene.withPrevious(null).withObjects(
                        scene.objects().stream().filter(o -> !o.remembered()).toList()));
            }
            writer.commit();
        }
        return new Result(scenes.size(), result.edited(), result.scenes().size(), result.passes(), seconds);
    }
}
