package org.scenes.tests.bench;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.LivePlayer;
import org.scenes.agent.net.ServerAddress;
import org.scenes.api.Side;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import org.scenes.simulator.server.SoccerServer;
import org.scenes.simulator.teacher.Teachers;

/**
 * One whole game of {@code scenes server} with two teacher teams of 11 players each, all 22
 * connected over loopback UDP with the project's live runtime in this JVM (a thread per player).
 * {@code synchronousGame}: how long a game takes in synchronous mode (the server and the
 * clients as fast as the cores allow). {@code realTimeGame}: a game at 100 ms per cycle; the
 * cycle-start lateness (p99 and max) is printed, the time is the game's length.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 0)
@Measurement(iterations = 1)
@Fork(1)
public class ServerBench {
    @Param({"6000"})
    public int cycles;

    @Param({"300"})
    public int realTimeCycles;

    @Param({"krislet"})
    public String teacher;

    @Benchmark
    public ServerResult synchronousGame() throws Exception {
        ServerResult result = game(true, cycles);
        System.out.printf(Locale.ROOT, "%n%d cycles, %d : %d, %d players, %d dropped, %.1f s%n", result.cycles(),
                result.scoreLeft(), result.scoreRight(), result.players(), result.dropped(), result.seconds());
        return result;
    }

    @Benchmark
    public ServerResult realTimeGame() throws Exception {
        ServerResult result = game(false, realTimeCycles);
        System.out.printf(Locale.ROOT, "%n%d cycles in real time, %d players, cycle-start lateness p50 %.2f ms,"
                + " p99 %.2f ms, max %.2f ms%n", result.cycles(), result.players(), result.latenessP50Millis(),
                result.latenessP99Millis(),
                result.latenessMaxMillis());
        return result;
    }

    private ServerResult game(boolean synch, int length) throws Exception {
        ServerConfig config = ServerConfig.defaults().withPort(0).withSynch(synch).withGame(length, 1)
                .withTimings(Duration.ofMillis(500), Duration.ofSeconds(5));
        ExecutorService executor = Executors.newSingleThreadExecutor();
        List<Thread> threads = new ArrayList<>();
        try (SoccerServer server = SoccerServer.open(config, line -> { })) {
            Future<ServerResult> running = executor.submit(() -> server.run(frame -> { }));
            BrainFactory brains = Teachers.byName(teacher);
            for (String team : List.of("Teal", "Amber")) {
                Side side = team.equals("Teal") ? Side.LEFT : Side.RIGHT;
                for (int unum = 1; unum <= 11; unum++) {
                    ClientOptions options = ClientOptions.of(new ServerAddress("127.0.0.1", server.port()), team)
                            .withTimeouts(Duration.ofSeconds(5), Duration.ofSeconds(30));
                    LivePlayer player = new LivePlayer(options,
                            brains.create(team, new Random(Simulator.brainSeed(1, side, unum))), false, n -> { });
                    Thread thread = new Thread(player, team + "-" + unum);
                    thread.start();
                    threads.add(thread);
                    if (!player.awaitAnswer(5, TimeUnit.SECONDS)) {
                        throw new IllegalStateException(team + " " + unum + " could not connect");
                    }
                }
            }
            ServerResult result = running.get(30, TimeUnit.MINUTES);
            for (Thread thread : threads) {
                thread.join(10_000);
            }
            return result;
        } finally {
            executor.shutdownNow();
        }
    }
}
