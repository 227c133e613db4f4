package org.scenes.spark;

import java.io.IOException;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;

/**
 * The scene files of a cross-validation as bytes, in fold order: what the driver broadcasts once
 * to every executor, which decodes them with the project's own reader.
 */
final class SceneData implements Serializable {
    private final ArrayList<String> names;
    private final ArrayList<byte[]> contents;

    SceneData(List<String> names, List<byte[]> contents) {
        this.names = new ArrayList<>(names);
        this.contents = new ArrayList<>(contents);
    }

    /** Reads the files (any Hadoop-compatible path or a local one) as they are, gzip or not. */
    static SceneData read(List<String> paths, HadoopFiles files) throws IOException {
        List<byte[]> contents = new ArrayList<>();
        for (String path : paths) {
            contents.add(files.readAll(path));
        }
        return new SceneData(paths, contents);
    }

    int size() {
        return names.size();
    }

    List<String> names() {
        return names;
    }

    /** Every file decoded; errors name the file as it was given. */
    List<SceneFile> decode() {
        List<SceneFile> files = new ArrayList<>();
        Path directory = null;
        try {
            directory = Files.createTempDirectory("scenes-spark-data");
            for (int i = 0; i < names.size(); i++) {
                String name = names.get(i);
                Path copy = directory.resolve(i + "-" + name.substring(name.lastIndexOf('/') + 1));
                Files.write(copy, contents.get(i));
                try {
                    files.add(SceneFileReader.read(copy));
                } finally {
                    Files.delete(copy);
                }
            }
            return files;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot stage the scene files in a temporary directory: " + e.getMessage(), e);
        } finally {
            if (directory != null) {
                try {
                    Files.deleteIfExists(directory);
                } catch (IOException e) {
                    // an empty temporary directory left behind loses nothing
                }
            }
        }
    }
}
