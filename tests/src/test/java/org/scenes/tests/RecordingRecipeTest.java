package org.scenes.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.DatagramSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 31.7: the documented recipe that records a game without rcssserver (server, proxy and two
 * teams started at once), pasted as one script, finishes by itself and leaves every log. Only its
 * ports are changed, to free ones, and {@code scenes} is this build's command line.
 */
@Tag("slow")
class RecordingRecipeTest {
    private static final Pattern SHELL_BLOCK = Pattern.compile("```sh\\n(.*?)```", Pattern.DOTALL);

    @TempDir
    Path dir;

    /** The documented block that starts a server, a proxy and teams, from README.md or docs/. */
    static String recipe() throws IOException {
        Path root = Path.of(System.getProperty("scenes.root", "."));
        List<Path> pages = new ArrayList<>(List.of(root.resolve("README.md")));
        try (Stream<Path> docs = Files.walk(root.resolve("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        for (Path page : pages) {
            Matcher block = SHELL_BLOCK.matcher(Files.readString(page));
            while (block.find()) {
                String text = block.group(1);
                if (text.contains("scenes server ") && text.contains("scenes proxy ") && text.contains("scenes team ")) {
                    return text;
                }
            }
        }
        throw new AssertionError("no recipe with scenes server, proxy and team in README.md or docs/");
    }

    private static int freePort() throws IOException {
        try (DatagramSocket socket = new DatagramSocket(0)) {
            return socket.getLocalPort();
        }
    }

    @Test
    void theRecordingRecipePastedAsOneBlockFinishesByItself() throws Exception {
        String recipe = recipe();
        assertTrue(recipe.strip().endsWith("wait"), "the recipe waits for its background jobs: " + recipe);
        String script = recipe.replace("6000", Integer.toString(freePort())).replace("7000", Integer.toString(freePort()));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String prelude = "scenes() { '" + java + "' -Xmx256m -cp '" + System.getProperty("java.class.path")
                + "' org.scenes.cli.Main \"$@\"; }\n";
        Path file = Files.writeString(dir.resolve("recipe.sh"), prelude + script);
        Process process = new ProcessBuilder("timeout", "300", "bash", file.toString()).directory(dir.toFile())
                .redirectErrorStream(true).redirectOutput(dir.resolve("out.txt").toFile()).start();
        assertTrue(process.waitFor(320, TimeUnit.SECONDS), "the recipe ends");
        String output = Files.readString(dir.resolve("out.txt"));
        assertEquals(0, process.exitValue(), output);
        assertTrue(output.contains("1 game ended: stopping"), output);
        List<String> proxyLogs = names(dir.resolve(argument(recipe, "scenes proxy ", "--out")));
        for (String team : List.of("Teal", "Amber")) {
            for (int unum = 1; unum <= 11; unum++) {
                assertTrue(proxyLogs.contains(team + "_" + unum + ".log"), team + "_" + unum + " in " + proxyLogs);
            }
        }
        List<String> serverLogs = names(dir.resolve(argument(recipe, "scenes server ", "--record")));
        Optional<String> game = serverLogs.stream().filter(n -> n.endsWith(".rcg")).findFirst();
        assertTrue(game.isPresent() && serverLogs.stream().anyMatch(n -> n.endsWith(".rcl")), serverLogs.toString());
        assertTrue(game.get().startsWith("Teal_") || game.get().startsWith("Amber_"), game.get());
    }

    /** The value of {@code option} on the recipe's line starting with {@code command}. */
    private static String argument(String recipe, String command, String option) {
        for (String line : recipe.split("\n")) {
            if (line.startsWith(command)) {
                List<String> words = List.of(line.split("\\s+"));
                return words.get(words.indexOf(option) + 1);
            }
        }
        throw new AssertionError("no '" + command + "' line in " + recipe);
    }

    private static List<String> names(Path directory) throws IOException {
        try (Stream<Path> files = Files.list(directory)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }
}
