package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetSocketAddress;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class ProxyCommandTest {
    private record Run(int exitCode, String err) {
    }

    private static Run run(String... args) {
        CommandLine commandLine = ScenesCommand.commandLine();
        StringWriter err = new StringWriter();
        commandLine.setErr(new PrintWriter(err));
        commandLine.setOut(new PrintWriter(new StringWriter()));
        int code = commandLine.execute(args);
        return new Run(code, err.toString());
    }

    @Test
    void parsesHostAndPort() {
        assertEquals(new InetSocketAddress("127.0.0.1", 6000), ProxyCommand.address("--server", "127.0.0.1:6000", -1));
        assertEquals(6001, ProxyCommand.address("--server", "[::1]:6001", -1).getPort());
    }

    @Test
    void badAddressesAreUsageErrorsNamingTheOption() {
        assertEquals("--server: expected HOST:PORT, not 'localhost'",
                assertThrows(UsageException.class, () -> ProxyCommand.address("--server", "localhost", -1)).getMessage());
        assertThrows(UsageException.class, () -> ProxyCommand.address("--server", "localhost:70000", -1));
        assertThrows(UsageException.class, () -> ProxyCommand.address("--server", "localhost:x", -1));
    }

    @Test
    void badOptionsExitWithUsageCode() {
        Run format = run("proxy", "--server", "127.0.0.1:6000", "--listen", "0", "--out", "build/tmp/proxy-test",
                "--format", "xml");
        assertEquals(ExitCodes.USAGE, format.exitCode());
        assertTrue(format.err().contains("--format: expected native or lsf, not 'xml'"), format.err());
        assertEquals(ExitCodes.USAGE, run("proxy", "--listen", "0", "--out", "x").exitCode());
        Run timeout = run("proxy", "--server", "127.0.0.1:6000", "--listen", "0", "--out", "build/tmp/proxy-test",
                "--idle-timeout", "0");
        assertEquals(ExitCodes.USAGE, timeout.exitCode());
    }
}
