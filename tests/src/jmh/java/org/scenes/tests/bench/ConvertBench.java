package org.scenes.tests.bench;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;
import org.scenes.api.Grid;
import org.scenes.internal.convert.LogReader;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

/**
 * Conversion throughput over the 27 recorded Krislet logs of the shared data set. One operation
 * converts all of them (about 79.4 MB of log text) into scenes, which go to a blackhole (writing
 * scene files is measured separately). Throughput in MB/s = 79.4 / (score in seconds); the
 * setup prints the exact size.
 * <ul>
 *   <li>{@code gzipLogs}: from the .lsf.gz files, decompression included, as {@code scenes convert} runs;</li>
 *   <li>{@code textInMemory}: from the decompressed text held in memory: parser and converter alone;</li>
 *   <li>{@code gzipLogsToSceneFile}: like {@code gzipLogs}, the scenes written to one plain JSON scene
 *       file (about 118 MB), as {@code scenes convert ... -o all.json} does.</li>
 * </ul>
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 3)
@Measurement(iterations = 5, time = 3)
@Fork(value = 1, jvmArgsAppend = "-Xmx1g")
public class ConvertBench {
    private List<Path> logs;
    private List<byte[]> texts;
    private Path sceneFile;

    @Setup
    public void load() throws IOException {
        Path data = Path.of(System.getProperty("scenes.shared", "../../shared"), "data", "krislet");
        try (Stream<Path> files = Files.walk(data)) {
            logs = files.filter(p -> p.toString().endsWith(".lsf.gz")).sorted().toList();
        }
        if (logs.size() != 27) {
            throw new IllegalStateException("expected the 27 shared Krislet logs under " + data + ", found " + logs.size());
        }
        texts = new ArrayList<>();
        long bytes = 0;
        for (Path log : logs) {
            try (InputStream in = Inputs.open(log)) {
                byte[] text = in.readAllBytes();
                texts.add(text);
                bytes += text.length;
            }
        }
        System.out.printf("%nConvertBench: %d logs, %.2f MB of log text per operation%n", logs.size(), bytes / 1e6);
        sceneFile = Files.createTempFile("convert-bench", ".json");
    }

    @TearDown
    public void removeSceneFile() throws IOException {
        Files.deleteIfExists(sceneFile);
    }

    @Benchmark
    public long gzipLogsToSceneFile() throws IOException {
        long scenes = 0;
        try (SceneFileWriter writer = SceneFileWriter.create(sceneFile,
                SceneFileHeader.of(Grid.DEFAULT, new SceneSource("27 shared logs", null)))) {
            for (Path log : logs) {
                scenes += SceneConverter.with(Grid.DEFAULT).build().convert(log, writer::write).scenes();
            }
            writer.commit();
        }
        return scenes;
    }

    @Benchmark
    public long gzipLogs(Blackhole sink) throws IOException {
        long scenes = 0;
        for (Path log : logs) {
            scenes += SceneConverter.with(Grid.DEFAULT).build().convert(log, sink::consume).scenes();
        }
        return scenes;
    }

    @Benchmark
    public long textInMemory(Blackhole sink) throws IOException {
        long scenes = 0;
        for (int i = 0; i < texts.size(); i++) {
            try (LogReader reader = LogReader.read(logs.get(i), new ByteArrayInputStream(texts.get(i)))) {
                scenes += SceneConverter.with(Grid.DEFAULT).build().convert(reader, sink::consume, b -> { }).scenes();
            }
        }
        return scenes;
    }
}
