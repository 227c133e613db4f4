package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.world.WorldAccuracy;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code scenes world-error GAME.rcg SCENES...}: the world models' errors against a game log's truth. */
@Command(name = "world-error", mixinStandardHelpOptions = true,
        description = {"How far the world models of scenes (convert --world) are from the true positions a game"
                + " log records: own position, body direction, ball position and velocity, in the player's own"
                + " frame, as medians and 90th percentiles."})
final class WorldErrorCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "GAME.rcg", description = "The game log of the game the scenes come from.")
    Path gameLog;

    @Parameters(index = "1..*", arity = "1..*", paramLabel = "SCENES",
            description = "Scene files of its players, or directories of them.")
    List<Path> scenes;

    @Override
    public Integer call() throws IOException {
        if (!Files.isRegularFile(gameLog)) {
            throw new UsageException("no game log " + gameLog);
        }
        WorldAccuracy accuracy = new WorldAccuracy(gameLog);
        for (Path path : files()) {
            accuracy.add(path);
        }
        WorldAccuracy.Report r = accuracy.report();
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%-26s %d (%d not yet located)%n", "Scenes with a world", r.scenes(), r.unlocated());
        out.printf(Locale.ROOT, "%-26s %8s %8s %8s%n", "error", "count", "median", "p90");
        line(out, "position (m)", r.position());
        line(out, "body direction (deg)", r.body());
        line(out, "ball position (m)", r.ball());
        line(out, "ball seen this cycle (m)", r.ballSeen());
        line(out, "ball velocity (m/cycle)", r.ballVelocity());
        out.flush();
        if (r.scenes() == 0) {
            spec.commandLine().getErr().println("scenes: error: no scene with a world model matches a cycle of "
                    + gameLog + " (converted with --world, from this game?)");
            return 1;
        }
        return 0;
    }

    private static void line(PrintWriter out, String name, WorldAccuracy.Summary s) {
        out.printf(Locale.ROOT, "%-26s %8d %8.2f %8.2f%n", name, s.count(), s.median(), s.p90());
    }

    private List<Path> files() throws IOException {
        List<Path> files = new ArrayList<>();
        for (Path path : scenes) {
            if (Files.isDirectory(path)) {
                files.addAll(SceneCompression.sceneFilesIn(path));
            } else if (Files.isRegularFile(path)) {
                files.add(path);
            } else {
                throw new UsageException("no scene file or directory " + path);
            }
        }
        return files;
    }
}
