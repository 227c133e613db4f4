package org.scenes.internal.scene;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import java.util.Locale;

/**
 * How a scene file is compressed, as its name says: {@code .json.gz}, {@code .json.zst} or plain
 * {@code .json}. Writers compress by the name ({@code AtomicOutput}); readers find out by the
 * bytes, so a file read back needs nothing of this.
 */
public enum SceneCompression {
    /** gzip at its default level: what every tool reads (zcat). */
    GZIP(".json.gz"),
    /** zstd at level 1: on scene JSON about a tenth of gzip's CPU, the size within 13 % (docs/scale.md). */
    ZSTD(".json.zst"),
    /** plain JSON. */
    NONE(".json");

    private final String suffix;

    SceneCompression(String suffix) {
        this.suffix = suffix;
    }

    /** The scene file's name for {@code base} (a log's or a player's name). */
    public String fileName(String base) {
        return base + suffix;
    }

    /** The option value that names this compression: gzip, zstd, none. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The compression {@code key} names, or null. */
    public static SceneCompression fromKey(String key) {
        for (SceneCompression compression : values()) {
            if (compression.key().equals(key)) {
                return compression;
            }
        }
        return null;
    }

    /** True for the names scene files are given: {@code .json}, {@code .json.gz}, {@code .json.zst}. */
    public static boolean isSceneFile(Path file) {
        return baseName(file) != null;
    }

    /** The scene files of {@code directory} (named as {@link #isSceneFile} says), sorted by name. */
    public static List<Path> sceneFilesIn(Path directory) throws IOException {
        try (Stream<Path> files = Files.list(directory)) {
            return files.filter(SceneCompression::isSceneFile).sorted().toList();
        }
    }

    /**
     * The name without its scene-file ending ({@code Teal_1} of {@code Teal_1.json.zst}), which
     * namesakes of another compression share; null for a file not named as a scene file.
     */
    public static String baseName(Path file) {
        Path name = file.getFileName();
        if (name == null) {
            return null;
        }
        String text = name.toString();
        for (SceneCompression compression : values()) {
            if (text.endsWith(compression.suffix) && text.length() > compression.suffix.length()) {
                return text.substring(0, text.length() - compression.suffix.length());
            }
        }
        return null;
    }
}
