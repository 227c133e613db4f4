package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.DatagramChannel;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Starting a team on a server: the options and the failures a user meets first. */
class TeamCommandTest {
    @TempDir
    Path dir;

    private final CommandRunner cli = new CommandRunner();

    /** A loopback port nobody listens on. */
    private static int freePort() throws Exception {
        try (DatagramChannel probe = DatagramChannel.open()) {
            probe.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            return ((InetSocketAddress) probe.getLocalAddress()).getPort();
        }
    }

    @Test
    void noServerIsOneLineAndExitOne() throws Exception {
        int port = freePort();
        assertEquals(ExitCodes.FAILURE, cli.run("team", "--teacher", "krislet", "--server", "127.0.0.1:" + port,
                "--players", "3", "--timeout", "0.3"));
        assertEquals("", cli.out());
        assertEquals("scenes: Krislet (not connected): no answer from a soccer server at 127.0.0.1:" + port
                + " to (init Krislet (version 9)) within 0.3 s", cli.err().strip());
    }

    @Test
    void playWithServerNeedsNoOutDirAndRefusesSimulatorOptions() throws Exception {
        int port = freePort();
        assertEquals(ExitCodes.USAGE, cli.run("play", dir.resolve("x.json"), "--server", "127.0.0.1:" + port,
                "--cycles", "100"));
        assertTrue(cli.err().contains("--cycles: only for the embedded simulator"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("play", dir.resolve("x.json"), "--metric", "ball-goal"));
        assertTrue(cli.err().contains("--out-dir: say where the player logs go"), cli.err());
    }

    @Test
    void badOptionsNameThemselves() {
        assertEquals(ExitCodes.USAGE, cli.run("team", "--teacher", "krislet", "--server", "localhost"));
        assertTrue(cli.err().contains("--server: expected HOST:PORT"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("team", "--teacher", "krislet", "--server", "127.0.0.1:6000",
                "--version", "6"));
        assertTrue(cli.err().contains("--version: protocol version must be 7 to 19, not 6"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("team", "--teacher", "nobody", "--server", "127.0.0.1:6000"));
        assertTrue(cli.err().contains("--teacher: unknown teacher 'nobody'; available: krislet, statebased"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("team", "--teacher", "krislet", "--server", "127.0.0.1:6000",
                "--players", "12"));
        assertTrue(cli.err().contains("--players: a team has 1 to 11 players, not 12"), cli.err());
        assertEquals(ExitCodes.USAGE, cli.run("team", "--teacher", "krislet"));
        assertTrue(cli.err().contains("--server: say which soccer server"), cli.err());
    }
}
