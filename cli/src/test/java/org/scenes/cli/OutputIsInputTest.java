package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

/**
 * Issue 31.1: an output that is one of the command's inputs, by file identity (the same name, a
 * symbolic link, a hard link, {@code ./x} for {@code x}), is refused before any work with exit 2,
 * and the input is left byte for byte as it was.
 */
class OutputIsInputTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    private static final String LOG = "(init l 1 before_kick_off)\n(see 0 ((b) 1 2) ((g r) 30 0))\n(dash 100)\n"
            + "(see 1 ((b) 1 2))\n(kick 100 0)\n";

    private Path scenes(String name, long seed) throws Exception {
        Random random = new Random(seed);
        Observer observer = new Observer("T", Side.LEFT, 1);
        Path file = dir.resolve(name);
        try (SceneFileWriter writer = SceneFileWriter.create(file,
                SceneFileHeader.of(Grid.DEFAULT, new SceneSource(name, observer)))) {
            for (int i = 0; i < 40; i++) {
                double distance = random.nextInt(4) == 0 ? 0.5 : 2 + random.nextInt(30);
                double direction = random.nextInt(3) == 0 ? 0 : random.nextInt(61) - 30;
                Action action = distance <= 1 ? Action.kick(100, 0) : direction == 0 ? Action.dash(50) : Action.turn(direction);
                writer.write(new Scene(i, observer, List.of(
                        SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT)),
                        List.of(action)));
            }
            writer.commit();
        }
        return file;
    }

    /** The command exits 2 with one line naming the option and the input, and the input is unchanged. */
    private void refused(Path input, String option, Object... args) throws Exception {
        byte[] before = Files.readAllBytes(input);
        assertEquals(ExitCodes.USAGE, cli.run(args), cli.err());
        String err = cli.err().strip();
        assertTrue(err.contains(option) && err.contains("is the input") && err.contains("would destroy"), err);
        assertFalse(err.contains("\tat "), err);
        assertArrayEquals(before, Files.readAllBytes(input), "the input is unchanged");
        assertEquals("", cli.out(), "no work was done");
    }

    @Test
    void convertRefusesToWriteOverItsLogWhateverTheSpelling() throws Exception {
        Path log = Files.writeString(dir.resolve("x.lsf"), LOG);
        refused(log, "-o", "convert", log, "-o", log);
        Path link = Files.createSymbolicLink(dir.resolve("link.json"), log);
        refused(log, "-o", "convert", log, "-o", link);
        Path hard = Files.createLink(dir.resolve("hard.json"), log);
        refused(log, "-o", "convert", log, "-o", hard);
        refused(log, "-o", "convert", log, "-o", dir.resolve(".").resolve("x.lsf"));
        // the output directory holds a link named like the log's scene file, pointing at the log
        Path out = Files.createDirectory(dir.resolve("out"));
        Files.createSymbolicLink(out.resolve("x.json.gz"), log);
        refused(log, "--out-dir", "convert", log, "--out-dir", out);
    }

    @Test
    void tuneCondenseExportValidateAndReplayRefuseTheirInputsAsOutputs() throws Exception {
        Path a = scenes("a.json", 1);
        Path b = scenes("b.json", 2);
        refused(a, "-o", "tune", "--train", a, b, "-o", a, "--quiet");
        refused(b, "--table", "tune", "--train", a, b, "-o", dir.resolve("t.json"), "--table",
                Files.createSymbolicLink(dir.resolve("b-link.json"), b), "--quiet");
        refused(a, "-o", "condense", "--train", a, b, "-o", a);
        refused(b, "-o", "export", "--format", "csv", a, b, "-o", b);
        Path csv = Files.createLink(dir.resolve("a.csv"), a);
        refused(a, "--predictions", "validate", "--train", a, "--test", b, "--predictions", csv);
        Path page = Files.createLink(dir.resolve("game.html"), a);
        refused(a, "-o", "replay", a, "-o", page);
    }

    @Test
    void anOutputBesideTheInputsStillWorks() throws Exception {
        Path log = Files.writeString(dir.resolve("x.lsf"), LOG);
        assertEquals(ExitCodes.OK, cli.run("convert", log, "-o", dir.resolve("x.json")), cli.err());
        assertEquals(LOG, Files.readString(log));
        assertTrue(Files.size(dir.resolve("x.json")) > 0);
    }
}
