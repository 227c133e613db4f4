package org.scenes.spark;

import java.io.IOException;
import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;

/** The driver's copy of a cross-validation's scene files. */
final class SweepInputs {
    private SweepInputs() {
    }

    /**
     * Local files are read where they are, so errors name them as the user wrote them; other
     * files are decoded from the bytes already read for the executors.
     */
    static List<SceneFile> decodeOnDriver(List<String> paths, SceneData data, HadoopFiles hadoop) throws IOException {
        List<SceneFile> files = new ArrayList<>();
        List<SceneFile> remote = null;
        for (int i = 0; i < paths.size(); i++) {
            String path = paths.get(i);
            if (hadoop.fileSystem(path).getUri().getScheme().equals("file")) {
                files.add(SceneFileReader.read(path.startsWith("file:") ? Path.of(URI.create(path))
                        : Path.of(path)));
            } else {
                if (remote == null) {
                    remote = data.decode();
                }
                files.add(remote.get(i));
            }
        }
        return files;
    }
}
