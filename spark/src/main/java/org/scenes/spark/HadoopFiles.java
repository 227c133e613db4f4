package org.scenes.spark;

import java.io.FileNotFoundException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.UUID;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FileStatus;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.Path;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.gamelog.ServerLogs;

/**
 * Files on any Hadoop-compatible file system: a path with a scheme ({@code hdfs://}, {@code s3a://},
 * {@code file://}) goes to that file system, a path without one is on the local disk of the machine
 * that reads or writes it (as the local commands read it). The local disk is used raw, without
 * Hadoop's checksum side files, so outputs are exactly what the local commands write.
 */
final class HadoopFiles {
    private final Configuration configuration;

    HadoopFiles(Configuration configuration) {
        this.configuration = configuration;
    }

    /** On an executor: the Hadoop configuration of its class path and environment. */
    static HadoopFiles fromEnvironment() {
        return new HadoopFiles(new Configuration());
    }

    FileSystem fileSystem(String path) throws IOException {
        URI uri = URI.create(path.replace(" ", "%20"));
        if (uri.getScheme() == null || uri.getScheme().length() == 1 || uri.getScheme().equals("file")) {
            return FileSystem.getLocal(configuration).getRaw();
        }
        return FileSystem.get(uri, configuration);
    }

    /** The path as the file system takes it: local paths made absolute against the working directory. */
    Path path(String path) throws IOException {
        FileSystem fs = fileSystem(path);
        if (fs.getUri().getScheme().equals("file")) {
            String local = path.startsWith("file:") ? URI.create(path).getPath() : path;
            return new Path(java.nio.file.Path.of(local).toAbsolutePath().normalize().toUri());
        }
        return fs.makeQualified(new Path(path));
    }

    byte[] readAll(String path) throws IOException {
        Path file = path(path);
        try (InputStream in = fileSystem(path).open(file)) {
            return in.readAllBytes();
        } catch (FileNotFoundException e) {
            throw new FileNotFoundException(path + ": no such file");
        }
    }

    /** The kind of server log a file is (by content, gzip or not), or null for any other file. */
    ServerLogs.Kind serverLogKind(String path) throws IOException {
        try (InputStream in = Inputs.decompressed(java.nio.file.Path.of(path), fileSystem(path).open(path(path)))) {
            return ServerLogs.detect(in);
        }
    }

    boolean isDirectory(String path) throws IOException {
        Path file = path(path);
        FileSystem fs = fileSystem(path);
        return fs.exists(file) && fs.getFileStatus(file).isDirectory();
    }

    boolean exists(String path) throws IOException {
        return fileSystem(path).exists(path(path));
    }

    /** The files and directories directly in a directory, sorted by name, as full paths. */
    List<FileStatus> list(String directory) throws IOException {
        List<FileStatus> entries = new ArrayList<>(List.of(fileSystem(directory).listStatus(path(directory))));
        entries.sort(Comparator.comparing(status -> status.getPath().getName()));
        return entries;
    }

    /** A local copy of a file (the file itself when it is local), for readers that take local paths. */
    java.nio.file.Path local(String path, java.nio.file.Path scratch) throws IOException {
        FileSystem fs = fileSystem(path);
        Path file = path(path);
        if (fs.getUri().getScheme().equals("file")) {
            return java.nio.file.Path.of(file.toUri());
        }
        java.nio.file.Path copy = scratch.resolve(file.getName());
        try (InputStream in = fs.open(file)) {
            Files.copy(in, copy, StandardCopyOption.REPLACE_EXISTING);
        }
        return copy;
    }

    /**
     * Puts a finished local file at {@code target}: copied under a temporary name beside it, then
     * renamed, so the target appears only complete (a rename is atomic on HDFS and local disks; on
     * object stores, which copy, it is as atomic as they allow). An earlier attempt's file is replaced.
     */
    void publish(java.nio.file.Path file, String target) throws IOException {
        FileSystem fs = fileSystem(target);
        Path destination = path(target);
        fs.mkdirs(destination.getParent());
        Path temporary = new Path(destination.getParent(), "." + destination.getName() + "." + UUID.randomUUID() + ".tmp");
        try (InputStream in = Files.newInputStream(file); OutputStream out = fs.create(temporary, false)) {
            in.transferTo(out);
        }
        try {
            if (fs.exists(destination)) {
                fs.delete(destination, false);
            }
            if (!fs.rename(temporary, destination)) {
                throw new IOException("cannot rename " + temporary + " to " + destination);
            }
        } finally {
            if (fs.exists(temporary)) {
                fs.delete(temporary, false);
            }
        }
    }
}
