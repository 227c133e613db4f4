package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.internal.convert.LogFormat;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.proxylog.ProxyLogLine;
import org.scenes.logproxy.ClientKind;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.Route;

/**
 * A whole recorded game replayed through two chained proxies (classic layout, then native):
 * both logs hold the original messages in the original order, and the converter turns all three
 * logs into the same scenes. Once with a recorded game (skipped without the shared recordings),
 * once with a simulated one.
 */
class RecordedGameThroughProxyTest {
    private static final Set<String> COMMANDS = Set.of("init", "dash", "turn", "kick", "move", "turn_neck", "catch",
            "say", "change_view", "bye", "tackle", "pointto", "attentionto");

    @TempDir
    Path out;

    @ParameterizedTest(name = "{0} game")
    @ValueSource(strings = {"recorded", "simulated"})
    void aRecordedGameSurvivesTheProxyAndConvertsToTheSameScenes(String game) throws Exception {
        Path original = KrisletLogs.carleton1(game);
        List<String> lines = new ArrayList<>();
        try (BufferedReader reader = new BufferedReader(new InputStreamReader(Inputs.open(original), StandardCharsets.UTF_8))) {
            for (String line = reader.readLine(); line != null; line = reader.readLine()) {
                lines.add(line);
            }
        }
        assertEquals("(init Carleton (version 9))", lines.get(0));
        assertEquals("(init l 1 before_kick_off)", lines.get(1), "the fake server answers the first Carleton player so");

        Path nativeLogs = out.resolve("native");
        Path lsfLogs = out.resolve("lsf");
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of("(sense_body 0)"));
                LogProxy nativeProxy = start(server.address(FakeSoccerServer.Port.PLAYER), nativeLogs, LogFormat.NATIVE);
                LogProxy lsfProxy = start(new InetSocketAddress(InetAddress.getLoopbackAddress(),
                        nativeProxy.listenPort(ClientKind.PLAYER)), lsfLogs, LogFormat.LSF);
                PlayerClient client = new PlayerClient(new InetSocketAddress(InetAddress.getLoopbackAddress(),
                        lsfProxy.listenPort(ClientKind.PLAYER)))) {
            client.init(lines.get(0) + '\0', 20_000);
            FakeSoccerServer.Client seen = server.clients().get(0);
            for (String line : lines.subList(2, lines.size())) {
                if (COMMANDS.contains(head(line))) {
                    await(() -> client.receivedCount() == seen.sentCount());
                    client.send(line);
                } else {
                    await(() -> seen.receivedCount() == client.sentCount());
                    seen.send((line + '\0').getBytes(StandardCharsets.UTF_8));
                }
            }
            await(() -> client.receivedCount() == seen.sentCount() && seen.receivedCount() == client.sentCount());
            lsfProxy.close();
            nativeProxy.close();
        }

        assertEquals(lines, Files.readAllLines(lsfLogs.resolve("Carleton_1.lsf"), StandardCharsets.UTF_8));
        List<String> logged = new ArrayList<>();
        for (String line : Files.readAllLines(nativeLogs.resolve("Carleton_1.log"), StandardCharsets.UTF_8)) {
            if (!ProxyLogLine.isComment(line)) {
                logged.add(ProxyLogLine.parse(line).text());
            }
        }
        assertEquals(lines, logged);

        List<Scene> expected = convert(original);
        assertTrue(expected.size() > 1000, "scenes in the original: " + expected.size());
        assertEquals(expected, convert(lsfLogs.resolve("Carleton_1.lsf")));
        assertEquals(expected, convert(nativeLogs.resolve("Carleton_1.log")));
    }

    private static LogProxy start(InetSocketAddress server, Path logs, LogFormat format) throws IOException {
        return LogProxy.start(new ProxyConfig(InetAddress.getLoopbackAddress(),
                List.of(new Route(ClientKind.PLAYER, 0, server)), logs, format, Duration.ofSeconds(120),
                Duration.ofSeconds(120), ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, ProxyConfig.DEFAULT_MAX_CLIENTS, line -> { }));
    }

    private static List<Scene> convert(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).strict(true).build().convert(log, scenes::add);
        return scenes;
    }

    private static String head(String message) {
        int end = 1;
        while (end < message.length() && message.charAt(end) != ' ' && message.charAt(end) != ')') {
            end++;
        }
        return message.substring(1, end);
    }

    private static void await(BooleanSupplier condition) {
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("a datagram did not arrive");
            }
            LockSupport.parkNanos(20_000);
        }
    }
}
