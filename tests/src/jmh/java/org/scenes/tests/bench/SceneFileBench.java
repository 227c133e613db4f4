package org.scenes.tests.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.openjdk.jmh.annotations.AuxCounters;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;
import org.scenes.simulator.SyntheticScenes;

/**
 * Scene files: one operation reads or writes a whole file. Secondary scores per second:
 * {@code scenes} and {@code megabytes} (of JSON text, so plain and gzip files compare by the
 * work done; the setup prints both file sizes). Sets ({@code source}): {@code krislet-player},
 * one player's converted log (Carleton_1 of the recorded Krislet game 1, about 2,500 scenes: the
 * file {@code scenes convert} writes per log), {@code krislet-game}, all ten players of that game
 * in one file (about 24,000 scenes), or {@code synthetic}, 10^5 scenes of {@link SyntheticScenes}
 * (seed 1); {@code format}: plain {@code json} or {@code json.gz}.
 * <ul>
 *   <li>{@code read}: {@link SceneFileReader} streaming every scene as a {@link Scene};</li>
 *   <li>{@code loadKnowledgeBase}: {@link KnowledgeBase#load}, what validation and the agent do;</li>
 *   <li>{@code write}: {@link SceneFileWriter}, temporary file and rename included.</li>
 * </ul>
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = "-Xmx2g")
public class SceneFileBench {
    static final int SYNTHETIC_SCENES = 100_000;

    @Param({"krislet-player", "krislet-game", "synthetic"})
    public String source;

    @Param({"json", "json.gz"})
    public String format;

    private List<Scene> data;
    private SceneFileHeader header;
    private Path directory;
    private Path file;
    private double megabytes;

    /** Per-iteration totals; JMH reports them per second. */
    @AuxCounters(AuxCounters.Type.OPERATIONS)
    @State(Scope.Thread)
    public static class Done {
        public long scenes;
        public double megabytes;

        @Setup(Level.Iteration)
        public void reset() {
            scenes = 0;
            megabytes = 0;
        }
    }

    @Setup
    public void prepare() throws IOException {
        long start = System.nanoTime();
        data = new ArrayList<>();
        if (source.startsWith("krislet")) {
            Path game = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet", "classic-game1");
            SceneConverter converter = SceneConverter.with(Grid.DEFAULT).build();
            String prefix = source.equals("krislet-player") ? "Carleton_1." : "";
            try (Stream<Path> logs = Files.list(game)) {
                for (Path log : logs.filter(p -> p.getFileName().toString().startsWith(prefix)
                        && p.toString().endsWith(".lsf.gz")).sorted().toList()) {
                    converter.convert(log, data::add);
                }
            }
            // a player's file names its observer once in the header, as the converter writes it
            header = SceneFileHeader.of(Grid.DEFAULT,
                    new SceneSource("classic-game1", prefix.isEmpty() ? null : data.get(0).observer()));
        } else {
            SyntheticScenes.generate(1, SYNTHETIC_SCENES, Grid.DEFAULT, data::add);
            header = SceneFileHeader.of(Grid.DEFAULT, new SceneSource("synthetic seed 1", null));
        }
        directory = Files.createTempDirectory("scene-file-bench");
        file = directory.resolve("scenes." + format);
        SceneFileWriter.write(file, new SceneFile(header, data));
        long text = 0;
        try (InputStream in = Inputs.open(file)) {
            byte[] buffer = new byte[1 << 16];
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                text += n;
            }
        }
        megabytes = text / 1e6;
        System.out.printf(Locale.ROOT, "%n[setup] %d scenes, %.1f MB of JSON, file %.1f MB, prepared in %.1f s%n",
                data.size(), megabytes, Files.size(file) / 1e6, (System.nanoTime() - start) / 1e9);
    }

    @TearDown
    public void clean() throws IOException {
        try (Stream<Path> files = Files.walk(directory)) {
            for (Path path : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(path);
            }
        }
    }

    @Benchmark
    public void read(Done done, Blackhole sink) {
        long count = 0;
        try (SceneFileReader reader = SceneFileReader.open(file)) {
            while (reader.hasNext()) {
                sink.consume(reader.next());
                count++;
            }
        }
        done.scenes += count;
        done.megabytes += megabytes;
    }

    @Benchmark
    public KnowledgeBase loadKnowledgeBase(Done done) {
        KnowledgeBase knowledge = KnowledgeBase.load(List.of(file), List::of);
        done.scenes += knowledge.size();
        done.megabytes += megabytes;
        return knowledge;
    }

    @Benchmark
    public void write(Done done) {
        try {
            SceneFileWriter.write(directory.resolve("written." + format), new SceneFile(header, data));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        done.scenes += data.size();
        done.megabytes += megabytes;
    }
}
