package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 31.3 from the command line: a non-finite or impossible number in a log, an option, a scene
 * file or a metric's answer gives one line naming where it is, never a scene file with it in and
 * never a result ranked by it.
 */
class ImpossibleNumbersTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    private static final String HEADER = "{\"format\":1,\n"
            + "\"grid\":{\"columns\":5,\"rows\":3,\"minAngle\":-45,\"maxAngle\":45,\"bounds\":[1,5]},\n"
            + "\"source\":{\"log\":\"x.lsf\",\"team\":\"T\",\"side\":\"l\",\"unum\":1},\n\"scenes\":[\n";

    private Path sceneFile(String name, String ballFields, String action) throws Exception {
        String scene = "{\"cycle\":%d,\"objects\":[{\"kind\":\"ball\",\"name\":\"b\",%s,\"cell\":[2,1]}],"
                + "\"actions\":[%s]}";
        String text = HEADER + String.format(scene, 1, "\"dist\":2,\"dir\":0", "{\"type\":\"dash\",\"power\":100,\"primary\":true}")
                + ",\n" + String.format(scene, 2, ballFields, action) + "\n]}\n";
        return Files.writeString(dir.resolve(name), text);
    }

    private void oneLine(String... parts) {
        String err = cli.err().strip();
        assertFalse(err.contains("\tat "), err);
        assertFalse(err.contains("Exception"), err);
        for (String part : parts) {
            assertTrue(err.contains(part), "'" + part + "' missing in: " + err);
        }
    }

    @Test
    void aNanBallIsAMalformedLineAndStrictStopsAtIt() throws Exception {
        Path log = Files.writeString(dir.resolve("nan.lsf"), "(init l 1 before_kick_off)\n"
                + "(see 0 ((b) 1 2) ((g r) 30 0))\n(dash 100)\n"
                + "(see 1 ((b) nan 2) ((g r) 30 0))\n(dash 100)\n"
                + "(see 2 ((b) 1e999 2) ((g r) 30 0))\n(kick 100 0)\n");
        assertEquals(ExitCodes.OK, cli.run("convert", log, "-o", dir.resolve("nan.json")), cli.err());
        assertTrue(cli.err().contains("nan.lsf:4") && cli.err().contains("not a finite number"), cli.err());
        assertTrue(cli.err().contains("nan.lsf:6"), cli.err());
        assertEquals(ExitCodes.OK, cli.run("show", dir.resolve("nan.json")), cli.err());
        assertFalse(cli.out().contains("Infinity") || cli.out().contains("NaN"), cli.out());
        assertEquals(ExitCodes.FAILURE, cli.run("convert", log, "--strict", "-o", dir.resolve("strict.json")));
        oneLine("nan.lsf:4");
        assertFalse(Files.exists(dir.resolve("strict.json")));
    }

    @Test
    void infiniteGridBoundsAreAUsageError() throws Exception {
        Path log = Files.writeString(dir.resolve("x.lsf"), "(init l 1 before_kick_off)\n(see 0 ((b) 1 2))\n(dash 100)\n");
        assertEquals(ExitCodes.USAGE, cli.run("convert", log, "--bounds", "1,Infinity", "-o", dir.resolve("x.json")));
        oneLine("--bounds", "finite");
        assertEquals(ExitCodes.USAGE, cli.run("convert", log, "--bounds", "1,NaN", "-o", dir.resolve("x.json")));
        assertFalse(Files.exists(dir.resolve("x.json")));
    }

    @Test
    void sceneFilesWithImpossibleNumbersOrIllTypedParametersAreRefusedWithTheirLine() throws Exception {
        Path good = sceneFile("good.json", "\"dist\":3,\"dir\":10", "{\"type\":\"turn\",\"moment\":10,\"primary\":true}");
        assertEquals(ExitCodes.OK, cli.run("validate", "--train", good, "--test", good), cli.err());
        String[][] bad = {
            {"far.json", "\"dist\":1e308,\"dir\":10", "{\"type\":\"turn\",\"moment\":10}", "'dist'"},
            {"negative.json", "\"dist\":-2,\"dir\":10", "{\"type\":\"turn\",\"moment\":10}", "'dist'"},
            {"spin.json", "\"dist\":3,\"dir\":1e6", "{\"type\":\"turn\",\"moment\":10}", "'dir'"},
            {"typed.json", "\"dist\":3,\"dir\":10", "{\"type\":\"dash\",\"power\":\"abc\"}", "'power' is a string"},
        };
        for (String[] file : bad) {
            Path path = sceneFile(file[0], file[1], file[2]);
            assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", good, "--test", path), file[0] + ": " + cli.err());
            oneLine(file[0] + ":6", file[3]);
        }
    }

    @Test
    void aScriptMetricReturningNanFailsNamingTheScript() throws Exception {
        Path script = Files.writeString(dir.resolve("broken.groovy"),
                "double distance(Scene query, Scene stored) {\n    return Double.NaN\n}\n");
        Path good = sceneFile("good.json", "\"dist\":3,\"dir\":10", "{\"type\":\"turn\",\"moment\":10,\"primary\":true}");
        assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", good, "--test", good, "--metric", "script:" + script));
        oneLine("broken.groovy", "returned NaN");
        Path negative = Files.writeString(dir.resolve("negative.groovy"),
                "double distance(Scene query, Scene stored) {\n    return -1\n}\n");
        assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", good, "--test", good, "--metric", "script:" + negative));
        oneLine("negative.groovy", "returned -1.0");
    }

    // ---- issue 31.8: messages -----------------------------------------------------------------

    @Test
    void aNewlineInAFileNameDoesNotBreakTheOneLine() throws Exception {
        Path file = Files.writeString(dir.resolve("new\nline.json"), "x");
        assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", file, "--self"));
        assertEquals(1, cli.err().strip().lines().count(), cli.err());
        oneLine("new\\x0Aline.json");
    }

    @Test
    void jsonErrorsNameNoLibrarySwitches() throws Exception {
        Path file = Files.writeString(dir.resolve("nan.json"), HEADER + "{\"cycle\":NaN}]}\n");
        assertEquals(ExitCodes.FAILURE, cli.run("validate", "--train", file, "--self"));
        oneLine("nan.json:5", "malformed JSON", "'NaN'");
        assertFalse(cli.err().contains("JsonReadFeature") || cli.err().contains("enable"), cli.err());
    }

    @Test
    void aNegativeValueAttachedToAnOptionIsNotAnUnknownOption() throws Exception {
        Path log = Files.writeString(dir.resolve("x.lsf"), "(init l 1 before_kick_off)\n(see 0 ((b) 1 2))\n(dash 100)\n");
        assertEquals(ExitCodes.USAGE, cli.run("convert", log, "--bounds=-1,5", "-o", dir.resolve("x.json")));
        assertTrue(cli.err().contains("option '--bounds' expects a value, not '-1,5'"), cli.err());
        assertFalse(cli.err().contains("Unknown option"), cli.err());
    }
}
