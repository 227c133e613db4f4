package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.PlayerReport;
import org.scenes.agent.net.ServerAddress;
import org.scenes.agent.net.TeamRunner;

/**
 * Issue 31.7: a team started a moment before its server (or proxy) listens still joins: the
 * client says its init again until the connect timeout, as a recipe pasted as one block needs.
 */
class InitRetryTest {
    private final ExecutorService executor = Executors.newSingleThreadExecutor();

    @AfterEach
    void shutDown() {
        executor.shutdownNow();
    }

    @Test
    void anInitNobodyHeardIsSentAgainUntilTheServerAnswers() throws Exception {
        InetSocketAddress address;
        String firstInit;
        Future<List<PlayerReport>> reports;
        // the port is ours first: the team's first init arrives where no server answers
        try (DatagramChannel silent = DatagramChannel.open()) {
            silent.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            address = (InetSocketAddress) silent.getLocalAddress();
            ClientOptions options = ClientOptions.of(new ServerAddress("127.0.0.1", address.getPort()), "Late")
                    .withTimeouts(Duration.ofSeconds(20), Duration.ofSeconds(2));
            reports = executor.submit(new TeamRunner(options, 1, LiveTeamTest.DASHER, 1, line -> { })::play);
            ByteBuffer buffer = ByteBuffer.allocate(1024);
            silent.receive(buffer); // blocks until the init came: no clock decides the order
            buffer.flip();
            firstInit = StandardCharsets.UTF_8.decode(buffer).toString().replace("\0", "");
        }
        assertEquals("(init Late (version 9))", firstInit);
        // now a server listens on that port: the next init reaches it
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of(), address.getPort())) {
            for (int i = 0; i < 500 && server.clients().isEmpty(); i++) {
                Thread.sleep(10); // polling a condition, bounded
            }
            assertEquals(1, server.clients().size(), "the team joined the server that started after it");
            server.clients().get(0).send("(hear 1 referee time_over)\0".getBytes(StandardCharsets.UTF_8));
            List<PlayerReport> result = reports.get(20, TimeUnit.SECONDS);
            assertEquals(0, TeamRunner.exitCode(result), result.toString());
            assertTrue(result.get(0).unum() == 1, result.toString());
        }
    }
}
