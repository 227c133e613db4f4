package org.scenes.app.convert;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Collectors;
import org.scenes.app.Progress;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.MalformedLine;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.scene.LazySceneFileWriter;

/**
 * {@code scenes convert LOG...}: player logs into one scene file ({@code -o}) or one per log
 * ({@code --out-dir}). A log with messages but no scene fails: with one file nothing is written,
 * with one per log the others are. Progress is counted in bytes of log text.
 */
public final class PlayerLogConversion {
    /** Logs this small, and fewer than two, show no progress. */
    private static final long LARGE_INPUT = 32L << 20;

    /**
     * What to convert and where.
     *
     * @param logs the player logs
     * @param file one scene file for all logs, or null
     * @param directory one scene file per log in this directory ({@link #outputNames}), or null
     */
    public record Request(List<Path> logs, Path file, Path directory, ConvertSettings settings) {
        public Request {
            logs = List.copyOf(logs);
            if ((file == null) == (directory == null)) {
                throw new IllegalArgumentException("one scene file or one directory, not both or neither");
            }
        }
    }

    /** What the front end hears while the logs are converted, in order. */
    public interface Listener {
        /** A malformed line skipped. */
        void malformed(MalformedLine line);

        /** A log converted; {@code failed} when it had messages but gave no scene. */
        void logDone(Path log, ConversionReport report, boolean failed);
    }

    /**
     * The outcome.
     *
     * @param total the counts of all logs
     * @param written the scene files written
     * @param failed the logs with messages but no scene
     * @param seconds the time taken
     */
    public record Result(ConversionReport total, List<Path> written, List<Path> failed, double seconds) {
    }

    private final Request request;
    private final List<Path> written = new CopyOnWriteArrayList<>();

    public PlayerLogConversion(Request request) {
        this.request = request;
    }

    /** The scene files complete so far; read from any thread (a shutdown hook's report). */
    public List<Path> written() {
        return List.copyOf(written);
    }

    /** The scene files expected. */
    public int expected() {
        return request.file() != null ? 1 : request.logs().size();
    }

    public Result run(Listener listener, Progress progress) throws IOException {
        List<Path> logs = request.logs();
        SceneConverter converter = request.settings().playerLogConverter(listener::malformed);
        ConversionReport total = new ConversionReport();
        List<Path> failed = new ArrayList<>();
        long started = System.nanoTime();
        TextProgress text = TextProgress.begin(logs, progress);
        try {
            if (request.file() != null) {
                try (LazySceneFileWriter writer = new LazySceneFileWriter(request.file(), request.settings().grid(),
                        sourceName(logs))) {
                    for (Path log : logs) {
                        ConversionReport report = convertLog(converter, log, writer, total, failed, text);
                        listener.logDone(log, report, noScenes(report));
                        text.logDone(log);
                    }
                    if (failed.isEmpty()) {
                        writer.commit();
                        written.add(request.file());
                    }
                }
            } else {
                Files.createDirectories(request.directory());
                List<String> names = outputNames(logs);
                for (int i = 0; i < logs.size(); i++) {
                    Path log = logs.get(i);
                    Path target = request.directory().resolve(request.settings().compression().fileName(names.get(i)));
                    try (LazySceneFileWriter writer = new LazySceneFileWriter(target, request.settings().grid(),
                            log.getFileName().toString())) {
                        ConversionReport report = convertLog(converter, log, writer, total, failed, text);
                        boolean noScenes = noScenes(report);
                        if (!noScenes) {
                            writer.commit();
                            written.add(target);
                        }
                        listener.logDone(log, report, noScenes);
                    }
                    text.logDone(log);
                }
            }
        } finally {
            progress.end();
        }
        return new Result(total, written(), List.copyOf(failed), (System.nanoTime() - started) / 1e9);
    }

    /**
     * Converts one log into {@code writer}, adding its counts to {@code total} and the log to
     * {@code failed} when it gave no scene; the caller commits the file.
     */
    private static ConversionReport convertLog(SceneConverter converter, Path log, LazySceneFileWriter writer,
                                               ConversionReport total, List<Path> failed, TextProgress text)
            throws IOException {
        ConversionReport report = converter.convert(log, SceneConverter.SceneSink.of(writer::write, writer::goalie),
                text::step);
        total.add(report);
        if (noScenes(report)) {
            failed.add(log);
        }
        return report;
    }

    /** A log with messages but no scene is a failed conversion; an empty log is not. */
    public static boolean noScenes(ConversionReport report) {
        return report.lines() > 0 && report.scenes() == 0 && (report.messages() > 0 || report.malformed() > 0);
    }

    /**
     * One output name per log: the log's name without extensions, prefixed with its directory's
     * name when two logs share a name (game1/Carleton_1 and game2/Carleton_1).
     *
     * @throws IllegalArgumentException when two logs would still share a name
     */
    public static List<String> outputNames(List<Path> logs) {
        Map<String, Long> counts = logs.stream().collect(Collectors.groupingBy(PlayerLogConversion::baseName,
                Collectors.counting()));
        List<String> names = new ArrayList<>();
        for (Path log : logs) {
            String name = baseName(log);
            Path parent = log.toAbsolutePath().getParent();
            if (counts.get(name) > 1 && parent != null && parent.getFileName() != null) {
                name = parent.getFileName() + "-" + name;
            }
            if (names.contains(name)) {
                throw new IllegalArgumentException("two logs would both be written as scene file " + name);
            }
            names.add(name);
        }
        return names;
    }

    /** The log's name without its extensions: {@code Carleton_1.lsf.gz} gives {@code Carleton_1}. */
    public static String baseName(Path log) {
        String name = log.getFileName().toString();
        for (String suffix : new String[] {".gz", ".zst", ".lsf", ".log", ".txt"}) {
            if (name.endsWith(suffix) && name.length() > suffix.length()) {
                name = name.substring(0, name.length() - suffix.length());
            }
        }
        return name;
    }

    private static String sourceName(List<Path> logs) {
        return logs.stream().map(p -> p.getFileName().toString()).collect(Collectors.joining(", "));
    }

    /**
     * Progress in bytes of log text, for several logs or a large one. The text of gzip logs is
     * unknown until read, so the total is re-estimated after each log from the ratio seen so far.
     */
    private static final class TextProgress {
        private final Progress progress;
        private final long compressedTotal;
        private long compressedDone;
        private long textDone;

        private TextProgress(Progress progress, long compressedTotal) {
            this.progress = progress;
            this.compressedTotal = compressedTotal;
        }

        static TextProgress begin(List<Path> logs, Progress progress) throws IOException {
            long size = 0;
            for (Path log : logs) {
                size += Files.isRegularFile(log) ? Files.size(log) : 0;
            }
            if (logs.size() < 2 && size < LARGE_INPUT) {
                progress.begin("Converting", 0);
                return new TextProgress(progress, size);
            }
            // about 10 bytes of text per compressed byte in recorded games; corrected as logs are read
            boolean compressed = logs.stream().map(l -> l.getFileName().toString())
                    .anyMatch(name -> name.endsWith(".gz") || name.endsWith(".zst"));
            progress.begin("Converting", compressed ? size * 10 : size);
            return new TextProgress(progress, size);
        }

        void step(long textBytes) {
            textDone += textBytes;
            progress.stepBy(textBytes);
        }

        void logDone(Path log) throws IOException {
            compressedDone += Files.isRegularFile(log) ? Files.size(log) : 0;
            if (compressedDone > 0) {
                double ratio = (double) textDone / compressedDone;
                progress.total(textDone + (long) (ratio * Math.max(0, compressedTotal - compressedDone)));
            }
        }
    }
}
