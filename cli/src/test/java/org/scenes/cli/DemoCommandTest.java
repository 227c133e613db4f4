package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class DemoCommandTest {
    @Test
    void runsSimulateConvertAndValidateInOrder(@TempDir Path dir) {
        CommandRunner cli = new CommandRunner();

        int status = cli.run("demo", "--cycles", "400", "--out-dir", dir);

        assertEquals(ExitCodes.OK, status, cli.err());
        String text = cli.out();
        int simulate = text.indexOf("$ scenes simulate");
        int convert = text.indexOf("$ scenes convert");
        int validate = text.indexOf("$ scenes validate");
        assertTrue(simulate >= 0 && simulate < convert && convert < validate, text);
        assertTrue(text.contains("Action accuracy"), text);
        assertTrue(Files.exists(dir.resolve("game1/scenes/Teal_1.json.gz")));
        assertTrue(Files.exists(dir.resolve("game2/logs/Amber_5.lsf.gz")));
    }
}
