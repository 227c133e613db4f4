package org.scenes.internal.match;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.function.Predicate;
import java.util.function.Supplier;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;

/**
 * The stored scenes a recognizer searches, built once and never changed. All scenes share one
 * grid: cells of different grids cannot be compared, so mixing them is refused. Scenes are held
 * compactly (about 7 bytes per seen object, see {@link CompactScenes}) and decoded on access, so
 * a million scenes fit in a few hundred megabytes; metrics pack what they compare once, when a
 * {@link Recognizer} is built.
 */
public final class KnowledgeBase {
    private final Grid grid;
    private final CompactScenes scenes;
    /** The first scenes, in order, that a recorded player played; those after them are labels ({@link #plus}). */
    private final int played;
    /** The scenes as the objects they were given as, when the caller keeps them anyway; else null. */
    private final List<Scene> held;
    /** The split by see age, made on first use (null before); {@link #ONE_AGE} when every scene has one age. */
    private volatile SortedMap<Integer, AgePart> byAge;
    private static final SortedMap<Integer, AgePart> ONE_AGE = Collections.emptySortedMap();

    private KnowledgeBase(Grid grid, CompactScenes scenes, int played, List<Scene> held) {
        this.grid = grid;
        this.scenes = scenes;
        this.played = played;
        this.held = held;
    }

    public static KnowledgeBase of(Grid grid, List<Scene> scenes) {
        Builder builder = builder(grid);
        scenes.forEach(builder::add);
        return builder.build();
    }

    /**
     * As {@link #of}, but reading gives the very objects of {@code scenes} instead of decoding them:
     * for a caller that keeps them anyway (cross-validation, which builds a recognizer per fold and
     * configuration), so packing a metric does not decode the whole knowledge base each time. The
     * scenes are equal either way, since the compact form is lossless.
     */
    public static KnowledgeBase held(Grid grid, List<Scene> scenes) {
        KnowledgeBase compact = of(grid, scenes);
        return new KnowledgeBase(grid, compact.scenes, compact.played, List.copyOf(scenes));
    }

    /** The scenes of one see age, as a knowledge base of their own, and where each is in the whole. */
    public record AgePart(KnowledgeBase knowledge, int[] indices) {
    }

    /**
     * The knowledge base split by see age (see {@link Recognizer}), ascending; empty when every
     * scene has one age. Made once per knowledge base, so every recognizer built on it shares it.
     */
    public SortedMap<Integer, AgePart> byAge() {
        SortedMap<Integer, AgePart> split = byAge;
        if (split == null) {
            synchronized (this) {
                split = byAge;
                if (split == null) {
                    split = splitByAge();
                    byAge = split;
                }
            }
        }
        return split;
    }

    private SortedMap<Integer, AgePart> splitByAge() {
        TreeMap<Integer, List<Integer>> indices = new TreeMap<>();
        for (int i = 0; i < size(); i++) {
            indices.computeIfAbsent(scenes.seeAge(i), age -> new ArrayList<>()).add(i);
        }
        if (indices.size() < 2) {
            return ONE_AGE;
        }
        TreeMap<Integer, AgePart> parts = new TreeMap<>();
        indices.forEach((age, members) -> {
            List<Scene> part = new ArrayList<>(members.size());
            members.forEach(i -> part.add(scene(i)));
            parts.put(age, new AgePart(held != null ? held(grid, part) : of(grid, part),
                    members.stream().mapToInt(Integer::intValue).toArray()));
        });
        return Collections.unmodifiableSortedMap(parts);
    }

    /** Collects scenes one at a time, so a knowledge base never needs them all as objects at once. */
    public static Builder builder(Grid grid) {
        return new Builder(grid);
    }

    public static final class Builder {
        private final Grid grid;
        private CompactScenes scenes;

        private Builder(Grid grid) {
            this.grid = grid;
            scenes = new CompactScenes(grid);
        }

        public Builder add(Scene scene) {
            if (scenes == null) {
                throw new IllegalStateException("the knowledge base was already built");
            }
            scenes.append(scene);
            return this;
        }

        /** Adds one player's scenes in order, through fresh transforms. */
        public Builder addSequence(Iterable<Scene> sequence, List<SceneTransform> transforms) {
            for (Scene scene : sequence) {
                storedScenes(scene, transforms).forEach(this::add);
            }
            return this;
        }

        public KnowledgeBase build() {
            if (scenes == null) {
                throw new IllegalStateException("the knowledge base was already built");
            }
            scenes.trim();
            KnowledgeBase knowledge = new KnowledgeBase(grid, scenes, scenes.size(), null);
            scenes = null;
            return knowledge;
        }
    }

    /**
     * Scenes of several files, each file passed through fresh transforms (made by
     * {@code transforms}) in order, since transforms such as memory follow one player's sequence.
     */
    public static KnowledgeBase fromFiles(List<SceneFile> files, Supplier<List<SceneTransform>> transforms) {
        return fromFiles(files, transforms, null);
    }

    /**
     * The same, also saying where each file's stored scenes end.
     *
     * @param ends null, or one slot per file: filled with the index after its last stored scene
     */
    public static KnowledgeBase fromFiles(List<SceneFile> files, Supplier<List<SceneTransform>> transforms, int[] ends) {
        if (files.isEmpty()) {
            throw new IllegalArgumentException("a knowledge base needs at least one scene file");
        }
        Builder builder = builder(SceneFile.commonGrid(files));
        for (int f = 0; f < files.size(); f++) {
            builder.addSequence(files.get(f).scenes(), transforms.get());
            if (ends != null) {
                ends[f] = builder.scenes.size();
            }
        }
        return builder.build();
    }

    /**
     * Reads the files (gzip or plain) one scene at a time into the knowledge base, so only the
     * compact form is ever held; errors name the file.
     */
    public static KnowledgeBase load(List<Path> paths, Supplier<List<SceneTransform>> transforms) {
        if (paths.isEmpty()) {
            throw new IllegalArgumentException("a knowledge base needs at least one scene file");
        }
        Grid grid = null;
        Builder builder = null;
        for (Path path : paths) {
            try (SceneFileReader reader = SceneFileReader.open(path)) {
                Grid fileGrid = reader.header().grid();
                if (grid == null) {
                    grid = fileGrid;
                    builder = builder(grid);
                } else {
                    Grid.common(List.of(paths.get(0), path), List.of(grid, fileGrid));
                }
                try {
                    builder.addSequence(() -> reader, transforms.get());
                } catch (IllegalArgumentException e) {
                    // a scene the knowledge base cannot hold: the data is at fault, so say whose
                    throw new IllegalArgumentException(path + ": " + e.getMessage(), e);
                }
            }
        }
        return builder.build();
    }

    /** One player's scenes through fresh transforms, in order. */
    public static List<Scene> transform(List<Scene> scenes, List<SceneTransform> transforms) {
        if (transforms.isEmpty()) {
            return scenes;
        }
        List<Scene> out = new ArrayList<>(scenes.size());
        for (Scene scene : scenes) {
            out.add(transformed(scene, transforms));
        }
        return out;
    }

    /** What a knowledge base stores for one player's scenes through fresh transforms, in order (see {@link SceneTransform#stored}). */
    public static List<Scene> stored(List<Scene> scenes, List<SceneTransform> transforms) {
        if (transforms.isEmpty()) {
            return scenes;
        }
        List<Scene> out = new ArrayList<>(scenes.size());
        for (Scene scene : scenes) {
            out.addAll(storedScenes(scene, transforms));
        }
        return out;
    }

    /** What the transforms store for one scene, in order: each transform's scenes for each scene before it. */
    private static List<Scene> storedScenes(Scene scene, List<SceneTransform> transforms) {
        List<Scene> current = List.of(scene);
        for (SceneTransform transform : transforms) {
            List<Scene> next = new ArrayList<>(current.size());
            for (Scene each : current) {
                next.addAll(transform.stored(each));
            }
            current = next;
        }
        return current;
    }

    private static Scene transformed(Scene scene, List<SceneTransform> transforms) {
        Scene current = scene;
        for (SceneTransform transform : transforms) {
            current = transform.apply(current);
        }
        return current;
    }

    public Grid grid() {
        return grid;
    }

    /**
     * These stored scenes (already transformed: copied as they are) followed by {@code sequences},
     * each through fresh transforms: how DAgger's labelled scenes join a knowledge base. A label
     * is a teacher's reply to a scene another player (the imitator) played on, so what followed
     * it in its sequence is not where its action led: it counts as no player's play
     * ({@link #played}).
     */
    public KnowledgeBase plus(List<List<Scene>> sequences, Supplier<List<SceneTransform>> transforms) {
        Builder builder = builder(grid);
        scenes().forEach(builder::add);
        for (List<Scene> sequence : sequences) {
            builder.addSequence(sequence, transforms.get());
        }
        KnowledgeBase built = builder.build();
        return new KnowledgeBase(grid, built.scenes, played, null);
    }

    /** These scenes without those {@code drop} matches, in order (itself when none does); labels stay labels. */
    public KnowledgeBase without(Predicate<Scene> drop) {
        Builder builder = builder(grid);
        int keptPlayed = 0;
        int index = 0;
        for (Scene scene : scenes()) {
            if (!drop.test(scene)) {
                builder.add(scene);
                keptPlayed += index < played ? 1 : 0;
            }
            index++;
        }
        KnowledgeBase built = builder.build();
        return built.size() == size() ? this : new KnowledgeBase(grid, built.scenes, keptPlayed, null);
    }

    /**
     * How many of the first scenes a recorded player played in order, so that what came after a
     * scene in its sequence is what its action led to; the scenes after them are labels
     * ({@link #plus}).
     */
    public int played() {
        return played;
    }

    /** The scenes in order, each decoded anew when read: iterate once rather than index repeatedly. */
    public List<Scene> scenes() {
        return held != null ? held : scenes;
    }

    public int size() {
        return scenes.size();
    }

    public Scene scene(int index) {
        return held != null ? held.get(index) : scenes.get(index);
    }

    /** The cycle of a stored scene, without decoding it. */
    public int cycle(int index) {
        return held != null ? held.get(index).cycle() : scenes.cycle(index);
    }

    /** Bytes of heap the stored scenes take (not counting what metrics pack from them). */
    public long storedBytes() {
        return scenes.storedBytes();
    }
}
