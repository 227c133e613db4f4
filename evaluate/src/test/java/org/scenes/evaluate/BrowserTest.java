package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.teacher.Teachers;

/**
 * The pages in a real browser: headless Chromium (Debian's {@code chromium}) opens them without
 * a console message, the script draws every replay, and a screenshot is taken
 * ({@code evaluate/build/screenshots/}, to look at). Skipped when Chromium is not installed.
 */
@Tag("slow")
class BrowserTest {
    private static String chromium;

    @TempDir
    Path directory;

    @BeforeAll
    static void findChromium() {
        for (String name : List.of("chromium", "chromium-browser", "google-chrome")) {
            for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
                if (Files.isExecutable(Path.of(dir, name))) {
                    chromium = Path.of(dir, name).toString();
                    return;
                }
            }
        }
    }

    @Test
    void theEvaluationReportOpensAndDrawsBothReplays() throws Exception {
        Assumptions.assumeTrue(chromium != null, "Chromium is not installed (apt-get install chromium): browser test skipped");
        GameSetup.Team teal = new GameSetup.Team("Teal", 2, Teachers.byName("krislet"));
        GameSetup.Team amber = new GameSetup.Team("Amber", 2, Teachers.byName("krislet"));
        Evaluation.Plan plan = new Evaluation.Plan(teal, Teachers.byName("statebased"), amber, 400, List.of(1L, 2L));
        Evaluation.Results results = Evaluation.run(plan, Arena.embedded(), done -> { });
        Path page = HtmlReport.write(directory.resolve("report"), "test report", Map.of("teacher", "krislet"),
                Comparison.of(results), results);
        String dom = open(page, "report.png");
        assertEquals(2, count(dom, "data-ready=\"true\""), "both replays drawn");
        assertTrue(dom.contains("<svg"), "the charts are inline SVG");
        Matcher status = Pattern.compile("class=\"replay-status\">cycle 0 · before_kick_off · Teal 0 : 0 Amber · ball 0.0 0.0 loose<")
                .matcher(dom);
        assertTrue(status.find(), "the replay shows the first frame's cycle, mode and score");
    }

    @Test
    void aReplayPageOpensAndShowsTheGame() throws Exception {
        Assumptions.assumeTrue(chromium != null, "Chromium is not installed (apt-get install chromium): browser test skipped");
        GameSetup.Team teal = new GameSetup.Team("Teal", 3, Teachers.byName("krislet"));
        GameSetup.Team amber = new GameSetup.Team("Amber", 3, Teachers.byName("statebased"));
        List<org.scenes.internal.gamelog.GameFrame> frames = new ArrayList<>();
        new org.scenes.simulator.Simulator(new GameSetup(teal, amber, 300, 3, null)).run(t -> { }, frames::add);
        Path page = directory.resolve("replay.html");
        ReplayPage.write(page, "Teal against Amber", frames);
        String dom = open(page, "replay.png");
        assertEquals(1, count(dom, "data-ready=\"true\""));
        assertTrue(dom.contains("max=\"" + (frames.size() - 1) + "\""), "the slider spans every frame");
        // The compact tracks decode to the game: move the slider to frames along the game and read
        // what the page shows of each (the player's own script, as a user's slider would).
        for (int index : List.of(frames.size() / 3, frames.size() - 1)) {
            String html = Files.readString(page).replace("</body>", "<script>var s = document.querySelector("
                    + "'input.replay-cycle'); s.value = '" + index + "'; s.dispatchEvent(new Event('input'));</script>"
                    + "</body>");
            Path moved = directory.resolve("moved-" + index + ".html");
            Files.writeString(moved, html);
            org.scenes.internal.gamelog.GameFrame frame = frames.get(index);
            String expected = String.format(java.util.Locale.ROOT, "cycle %d · %s · Teal %d : %d Amber · ball %.1f %.1f",
                    frame.time(), frame.playMode(), frame.scoreLeft(), frame.scoreRight(), frame.ball().x(),
                    frame.ball().y()).replace("-0.0", "0.0") + holder(frame);
            assertTrue(open(moved, "replay-" + index + ".png").contains("class=\"replay-status\">" + expected + "<"),
                    "frame " + index + " shows " + expected);
        }
    }

    /** What the status line says of the ball's owner: the nearest player within kicking reach. */
    private static String holder(org.scenes.internal.gamelog.GameFrame frame) {
        String holder = " loose";
        double nearest = ReplayPage.KICKABLE;
        for (org.scenes.internal.gamelog.PlayerState p : frame.players()) {
            double distance = Math.hypot(p.x() - frame.ball().x(), p.y() - frame.ball().y());
            if (distance <= nearest) {
                nearest = distance;
                holder = " with " + (p.side() == org.scenes.api.Side.LEFT ? frame.leftTeam() : frame.rightTeam()) + " " + p.unum();
            }
        }
        return holder;
    }

    /** Opens the page headless; fails on any console message; saves a screenshot; returns the DOM after the scripts ran. */
    private String open(Path page, String screenshot) throws IOException, InterruptedException {
        Path shots = Path.of(System.getProperty("scenes.root", "."), "evaluate", "build", "screenshots");
        Files.createDirectories(shots);
        List<String> common = List.of(chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                "--enable-logging=stderr", "--v=0", "--virtual-time-budget=3000", "--user-data-dir="
                        + directory.resolve("profile"));
        List<String> dump = new ArrayList<>(common);
        dump.addAll(List.of("--dump-dom", page.toUri().toString()));
        Path dom = directory.resolve("dom.html");
        Path log = directory.resolve("console.log");
        run(dump, dom, log);
        List<String> console = Files.readAllLines(log, StandardCharsets.UTF_8).stream()
                .filter(line -> line.contains(":CONSOLE")).toList();
        assertEquals(List.of(), console, "console messages");
        List<String> shot = new ArrayList<>(common);
        shot.addAll(List.of("--window-size=1300,1000", "--screenshot=" + shots.resolve(screenshot), page.toUri().toString()));
        run(shot, directory.resolve("shot.out"), directory.resolve("shot.err"));
        assertTrue(Files.size(shots.resolve(screenshot)) > 10_000, "a screenshot with something on it");
        return Files.readString(dom, StandardCharsets.UTF_8);
    }

    private static void run(List<String> command, Path out, Path err) throws IOException, InterruptedException {
        Process process = new ProcessBuilder(command).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!process.waitFor(90, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("Chromium did not finish in 90 s: " + command);
        }
    }

    private static int count(String text, String part) {
        int count = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
            count++;
        }
        return count;
    }
}
