package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.scenes.fakeserver.ProxyLogs.assertSameDatagrams;
import static org.scenes.fakeserver.ProxyLogs.unpadded;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.internal.proxylog.Direction;

/** {@code scenes proxy} as its own process: SIGTERM completes every log. */
class ProxyProcessTest {
    @TempDir
    Path out;

    private Path console;
    private Path logs;

    private List<String> output() throws IOException {
        return Files.exists(console) ? Files.readAllLines(console, StandardCharsets.UTF_8) : List.of();
    }

    /** The sensing of a recorded player (when the shared recordings are present) or of a simulated one. */
    @ParameterizedTest(name = "{0} game")
    @ValueSource(strings = {"recorded", "simulated"})
    void sigtermWritesEveryMessageAndCompletesTheLogs(String game) throws Exception {
        Path recorded = KrisletLogs.carleton1(game);
        try (FakeSoccerServer server = FakeSoccerServer.start(FakeSoccerServer.recordedSensing(recorded, 200))) {
            console = out.resolve("console.txt");
            logs = out.resolve("logs");
            int listen;
            try (DatagramSocket probe = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
                listen = probe.getLocalPort();
            }
            InetSocketAddress serverPort = server.address(FakeSoccerServer.Port.PLAYER);
            Process proxy = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", System.getProperty("java.class.path"), "org.scenes.cli.Main", "proxy",
                    "--server", "127.0.0.1:" + serverPort.getPort(), "--listen", String.valueOf(listen),
                    "--bind", "127.0.0.1", "--out", logs.toString())
                    .redirectErrorStream(true).redirectOutput(console.toFile()).start();
            try {
                long deadline = System.currentTimeMillis() + 60_000;
                while (output().stream().noneMatch(l -> l.startsWith("logging to"))) {
                    assertTrue(proxy.isAlive() && System.currentTimeMillis() < deadline, "proxy did not start: " + output());
                    PlayerClient.sleep(20);
                }
                try (PlayerClient client = new PlayerClient(new InetSocketAddress(InetAddress.getLoopbackAddress(), listen))) {
                    client.init("(init Carleton (version 9))\0", 20_000);
                    FakeSoccerServer.Client seen = server.clients().get(0);
                    for (int i = 0; i < 100; i++) {
                        client.send("(dash " + i + ")");
                        server.replay(1);
                    }
                    client.awaitReceived(seen.sent().size(), 20_000);
                    while (seen.receivedCount() < client.sent().size()) {
                        assertTrue(System.currentTimeMillis() < deadline, "server did not get everything");
                        PlayerClient.sleep(5);
                    }
                    proxy.destroy(); // SIGTERM
                    assertTrue(proxy.waitFor(30, TimeUnit.SECONDS), "proxy did not exit on SIGTERM");

                    ProxyLogs log = ProxyLogs.read(logs.resolve("Carleton_1.log"));
                    assertSameDatagrams(unpadded(client.sent()), log.messages(Direction.CLIENT_TO_SERVER), "logged c2s");
                    assertSameDatagrams(unpadded(seen.sent()), log.messages(Direction.SERVER_TO_CLIENT), "logged s2c");
                    assertEquals("# end proxy stopped", log.lastComment());
                    List<String> output = output();
                    assertTrue(output.stream().anyMatch(l -> l.startsWith("forwarded 101 to server, 101 to clients")), output.toString());
                }
            } finally {
                proxy.destroyForcibly();
            }
        }
    }
}
