package org.scenes.cli;

import com.fasterxml.jackson.core.type.TypeReference;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.internal.convert.SceneComparison;
import org.scenes.internal.scene.SceneCompression;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code scenes compare A B}: how close two scene files of one player are. */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = {"Compare two scene files of one player (e.g. rebuilt from a game log and converted from"
                + " the player's own log): scenes of the same cycle, the share of objects present in both,"
                + " distance and direction errors, and whether the paired actions agree."})
final class CompareCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "A", description = "A scene file (.json, .json.gz or .json.zst), or a directory of them.")
    Path first;

    @Parameters(index = "1", paramLabel = "B", description = {"The scene file to compare it with, or a directory:"
            + " its files of the same names, whatever their compression (every player of a game): each player's figures,"
            + " then their sum."})
    Path second;

    @Option(names = "--json", description = "Print the figures as JSON.")
    boolean json;

    @Override
    public Integer call() throws Exception {
        if (Files.isDirectory(first) != Files.isDirectory(second)) {
            throw new UsageException("compare two scene files or two directories, not " + first + " and " + second);
        }
        PrintWriter out = spec.commandLine().getOut();
        ObjectMapper mapper = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
        if (!Files.isDirectory(first)) {
            SceneComparison.Result r = new SceneComparison().compare(first, second);
            if (json) {
                out.println(mapper.writeValueAsString(r));
            } else {
                print(out, r);
            }
            out.flush();
            return ExitCodes.OK;
        }
        List<Path> left = new ArrayList<>();
        List<Path> right = new ArrayList<>();
        // namesakes: the same player's file, whatever each side's compression (Teal_1.json.gz, Teal_1.json.zst)
        Map<String, Path> seconds = new HashMap<>();
        for (Path file : SceneCompression.sceneFilesIn(second)) {
            if (Files.isRegularFile(file)) {
                seconds.putIfAbsent(SceneCompression.baseName(file), file);
            }
        }
        for (Path file : SceneCompression.sceneFilesIn(first)) {
            Path other = seconds.get(SceneCompression.baseName(file));
            if (other != null) {
                left.add(file);
                right.add(other);
            }
        }
        if (left.isEmpty()) {
            throw new UsageException("no scene file of " + first + " has a namesake in " + second);
        }
        SceneComparison comparison = new SceneComparison();
        List<Map<String, Object>> players = new ArrayList<>();
        for (int i = 0; i < left.size(); i++) {
            SceneComparison.Result one = comparison.compare(left.get(i), right.get(i));
            String name = left.get(i).getFileName().toString();
            if (json) {
                Map<String, Object> player = new LinkedHashMap<>();
                player.put("file", name);
                player.putAll(mapper.convertValue(one, new TypeReference<Map<String, Object>>() { }));
                players.add(player);
            } else {
                out.printf(Locale.ROOT, "%-26s %s%n", "File", name);
                print(out, one);
                out.println();
            }
        }
        SceneComparison.Result all = comparison.compare(left, right);
        if (json) {
            // the summed figures keep their keys at the top; each player's are under "players"
            Map<String, Object> result = new LinkedHashMap<>(
                    mapper.convertValue(all, new TypeReference<Map<String, Object>>() { }));
            result.put("players", players);
            out.println(mapper.writeValueAsString(result));
        } else {
            out.printf(Locale.ROOT, "%-26s %d of the same name, summed%n", "Files", left.size());
            print(out, all);
        }
        out.flush();
        return ExitCodes.OK;
    }

    private static void print(PrintWriter out, SceneComparison.Result r) {
        out.printf(Locale.ROOT, "%-26s %s | %s%n", "Players", r.observerA().label(), r.observerB().label());
        out.printf(Locale.ROOT, "%-26s %d | %d, %d of the same cycle%n", "Scenes", r.scenesA(), r.scenesB(),
                r.paired());
        out.printf(Locale.ROOT, "%-26s %.3f %% (%d of %d | %d)%n", "Objects in both", 100 * r.matchedShare(),
                r.matched(), r.objectsA(), r.objectsB());
        out.printf(Locale.ROOT, "%-26s %.3f %% within one step; mean %.4f m, p99 under %.2f m, max %.2f m%n",
                "Distance error", 100 * r.distanceWithinStepShare(), r.distanceErrorMean(), r.distanceErrorP99(),
                r.distanceErrorMax());
        out.printf(Locale.ROOT, "%-26s %.3f %% within 1 degree; mean %.4f, p99 under %.1f, max %.1f degrees%n",
                "Direction error", 100 * r.directionWithinStepShare(), r.directionErrorMean(), r.directionErrorP99(),
                r.directionErrorMax());
        out.printf(Locale.ROOT, "%-26s %.3f %% same type, %.3f %% same command%n", "Actions agree",
                100 * r.actionTypeShare(), 100 * r.actionShare());
    }
}
