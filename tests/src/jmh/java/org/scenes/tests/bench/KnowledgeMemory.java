package org.scenes.tests.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.stream.Stream;
import org.scenes.api.Grid;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * Heap taken by a knowledge base of real-size scenes and by each metric's packed form of it
 * ({@code gradle :tests:memoryBench}, run with -Xmx512m: finishing at all shows the target is met).
 * The scenes are the 27 Krislet logs' scenes, repeated until there are enough, each repetition
 * moving every object by a few tenths of a metre and a degree or two (the server's steps), so
 * no two stored scenes are the same and each keeps its real object count. Heap is measured
 * after full collections, as used heap of the whole JVM minus what it used before building.
 */
public final class KnowledgeMemory {
    private KnowledgeMemory() {
    }

    public static void main(String[] args) throws IOException {
        int count = 1_000_000;
        List<String> metrics = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--scenes" -> count = Integer.parseInt(args[++i]);
                case "--metric" -> metrics.add(args[++i]);
                default -> throw new IllegalArgumentException("unknown option " + args[i]
                        + "; use --scenes N and --metric NAME[,option=value...] (repeatable)");
            }
        }
        if (metrics.isEmpty()) {
            metrics = List.of("ball-goal", "continuous");
        }
        Path krislet = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet");
        long before = usedHeap();
        KnowledgeBase real = realScenes(krislet);
        long start = System.nanoTime();
        KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
        Random random = new Random(7);
        for (int i = 0; i < count; i++) {
            Scene scene = real.scene(i % real.size());
            builder.add(i < real.size() ? scene : moved(scene, random));
        }
        KnowledgeBase knowledge = builder.build();
        real = null;
        long afterBase = usedHeap();
        long objects = 0;
        for (int i = 0; i < knowledge.size(); i += 1000) {
            objects += knowledge.scene(i).objects().size();
        }
        System.out.printf(Locale.ROOT, "%,d scenes (%.1f objects per scene), built in %.1f s; max heap %,d MB%n",
                knowledge.size(), objects / Math.ceil(knowledge.size() / 1000.0), (System.nanoTime() - start) / 1e9,
                Runtime.getRuntime().maxMemory() >> 20);
        System.out.printf(Locale.ROOT, "%-36s %,10d MB  (%.0f bytes per scene; store %,d MB)%n", "knowledge base",
                (afterBase - before) >> 20, (double) (afterBase - before) / knowledge.size(), knowledge.storedBytes() >> 20);
        PluginRegistry registry = PluginRegistry.load();
        List<Recognizer> kept = new ArrayList<>();
        long previous = afterBase;
        for (String spec : metrics) {
            String[] parts = spec.split(",");
            PluginConfig chosen = PluginConfig.DEFAULT.withOptions(
                    BenchSets.options(Arrays.copyOfRange(parts, 1, parts.length)));
            long built = System.nanoTime();
            Recognizer recognizer = new Recognizer(knowledge, () -> registry.metric(parts[0], chosen), 1);
            double seconds = (System.nanoTime() - built) / 1e9;
            kept.add(recognizer); // every recognizer stays alive: the figures add up to the total
            recognizer.nearest(knowledge.scene(12345 % knowledge.size()));
            long now = usedHeap();
            System.out.printf(Locale.ROOT, "%-36s %,10d MB  (%.0f bytes per scene; packed in %.1f s)%n",
                    "+ " + spec, (now - previous) >> 20, (double) (now - previous) / knowledge.size(), seconds);
            previous = now;
        }
        System.out.printf(Locale.ROOT, "%-36s %,10d MB for %d recognizer(s)%n", "total", (previous - before) >> 20, kept.size());
    }

    private static KnowledgeBase realScenes(Path krislet) throws IOException {
        List<Path> logs;
        try (Stream<Path> files = Files.walk(krislet)) {
            logs = files.filter(p -> p.toString().endsWith(".lsf.gz")).sorted().toList();
        }
        KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
        for (Path log : logs) {
            SceneConverter.with(Grid.DEFAULT).build().convert(log, builder::add);
        }
        return builder.build();
    }

    /** The scene with every object moved by the server's quantisation steps. */
    private static Scene moved(Scene scene, Random random) {
        List<SeenObject> objects = new ArrayList<>(scene.objects().size());
        for (SeenObject o : scene.objects()) {
            double distance = Double.isNaN(o.distance()) ? o.distance()
                    : Math.max(0, Math.round(o.distance() * 10 + random.nextInt(7) - 3) / 10.0);
            double direction = Double.isNaN(o.direction()) ? o.direction() : o.direction() + random.nextInt(5) - 2;
            objects.add(new SeenObject(o.kind(), o.name(), o.team(), o.uniformNumber(), o.goalie(), o.relation(),
                    distance, direction, o.distanceChange(), o.directionChange(), o.bodyFacing(), o.headFacing(),
                    o.pointingDirection(), o.mark(), Grid.DEFAULT.cell(distance, direction)));
        }
        return new Scene(scene.cycle(), scene.observer(), objects, scene.actions());
    }

    private static long usedHeap() {
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        return memory.getHeapMemoryUsage().getUsed();
    }
}
