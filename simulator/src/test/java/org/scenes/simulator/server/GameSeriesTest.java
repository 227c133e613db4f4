package org.scenes.simulator.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The seeds of a series and its stop; the games themselves are played in LiveEvaluationTest. */
class GameSeriesTest {
    private static final ServerConfig CONFIG = ServerConfig.defaults().withPort(0).withGame(100, 5)
            .withTimings(Duration.ofMillis(100), Duration.ofSeconds(1));

    @Test
    void kGamesInARowShareASeed() {
        GameSeries series = new GameSeries(CONFIG, 6, 2, line -> { });
        List<Long> seeds = new ArrayList<>();
        for (int game = 0; game < 6; game++) {
            seeds.add(series.seed(game));
        }
        assertEquals(List.of(5L, 5L, 6L, 6L, 7L, 7L), seeds);
        assertEquals(List.of(5L, 6L), List.of(new GameSeries(CONFIG, 2, 1, l -> { }).seed(0),
                new GameSeries(CONFIG, 2, 1, l -> { }).seed(1)));
        assertThrows(IllegalArgumentException.class, () -> new GameSeries(CONFIG, 0, 1, l -> { }));
        assertThrows(IllegalArgumentException.class, () -> new GameSeries(CONFIG, 2, 0, l -> { }));
    }

    @Test
    void aStopWhileWaitingForTeamsEndsTheSeries() throws Exception {
        GameSeries series = new GameSeries(CONFIG, 3, 1, line -> { });
        List<Integer> started = new ArrayList<>();
        ExecutorService executor = Executors.newSingleThreadExecutor();
        try {
            Future<List<ServerResult>> running = executor.submit(() -> series.run(s -> {
                synchronized (started) {
                    started.add(s[0]);
                }
            }, result -> { }, frame -> { }));
            for (int i = 0; i < 100; i++) {
                synchronized (started) {
                    if (!started.isEmpty()) {
                        break;
                    }
                }
                Thread.sleep(50);
            }
            series.stop();
            List<ServerResult> results = running.get(10, TimeUnit.SECONDS);
            assertEquals(List.of(1), started, "the first game listened, no other");
            assertEquals(1, results.size());
            assertEquals(true, results.get(0).stopped());
        } finally {
            executor.shutdownNow();
        }
    }
}
