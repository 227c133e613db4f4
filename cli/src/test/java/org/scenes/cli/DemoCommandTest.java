package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class DemoCommandTest {
    @Test
    void runsSimulateConvertValidatePlayAndEvaluateInOrder(@TempDir Path dir) throws Exception {
        CommandRunner cli = new CommandRunner();

        int status = cli.run("demo", "--cycles", "400", "--evaluate-cycles", "300", "--out-dir", dir);

        assertEquals(ExitCodes.OK, status, cli.err());
        String text = cli.out();
        int simulate = text.indexOf("$ scenes simulate");
        int convert = text.indexOf("$ scenes convert");
        int validate = text.indexOf("$ scenes validate");
        int play = text.indexOf("$ scenes play");
        int evaluate = text.indexOf("$ scenes evaluate");
        assertTrue(simulate >= 0 && simulate < convert && convert < validate && validate < play && play < evaluate, text);
        assertTrue(text.contains("student-driven agreement"), text);
        assertTrue(text.contains("Evaluation report      " + dir.resolve("evaluation/index.html").toAbsolutePath()), text);
        assertTrue(Files.readString(dir.resolve("validation.txt")).contains("Action accuracy"));
        assertTrue(Files.readString(dir.resolve("validation.svg")).contains("<svg"));
        assertTrue(Files.readString(dir.resolve("evaluation/index.html")).contains("class=\"replay\""));
        assertTrue(text.contains("Action accuracy"), text);
        assertTrue(Files.exists(dir.resolve("game1/scenes/Teal_1.json.gz")));
        assertTrue(Files.exists(dir.resolve("game2/logs/Amber_5.lsf.gz")));
    }
}
