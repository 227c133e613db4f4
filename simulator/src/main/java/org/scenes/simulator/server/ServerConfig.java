package org.scenes.simulator.server;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;

/**
 * How {@link SoccerServer} runs a game.
 *
 * @param host the address to listen on (loopback by default)
 * @param port the init port (6000 like rcssserver; 0 for any free port)
 * @param synch synchronous mode: a cycle ends when every player sent {@code (done)} after {@code (think)}
 * @param cycles the game length (half time at half)
 * @param seed the seed of all the server's randomness
 * @param recordDirectory where the game log and command log go; null for none
 * @param teamsWait how long to wait for the second team after the first player connected;
 *                  null to wait as long as it takes
 * @param settle how long no new player must have connected before kick-off preparations start
 * @param thinkTimeout in synchronous mode, how long a player may take to send {@code (done)}
 *                     before it is dropped
 */
public record ServerConfig(String host, int port, boolean synch, int cycles, long seed, Path recordDirectory,
                           Duration teamsWait, Duration settle, Duration thinkTimeout) {
    public static final int DEFAULT_PORT = 6000;
    public static final Duration DEFAULT_SETTLE = Duration.ofSeconds(1);
    /** rcssserver's own limit for a cycle's wait in synchronous mode (25 x 50 ms). */
    public static final Duration DEFAULT_THINK_TIMEOUT = Duration.ofMillis(1250);

    public ServerConfig {
        Objects.requireNonNull(host, "host");
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be 0 to 65535, not " + port);
        }
        if (cycles < 1) {
            throw new IllegalArgumentException("cycles must be at least 1, not " + cycles);
        }
        Objects.requireNonNull(settle, "settle");
        Objects.requireNonNull(thinkTimeout, "thinkTimeout");
        if (teamsWait != null && teamsWait.isNegative()) {
            throw new IllegalArgumentException("teams-wait must not be negative");
        }
    }

    /** Defaults: loopback, port 6000, real time, 6000 cycles, seed 1, no logs, wait for both teams. */
    public static ServerConfig defaults() {
        return new ServerConfig("127.0.0.1", DEFAULT_PORT, false, 6000, 1, null, null, DEFAULT_SETTLE,
                DEFAULT_THINK_TIMEOUT);
    }

    public ServerConfig withPort(int newPort) {
        return new ServerConfig(host, newPort, synch, cycles, seed, recordDirectory, teamsWait, settle, thinkTimeout);
    }

    public ServerConfig withSynch(boolean newSynch) {
        return new ServerConfig(host, port, newSynch, cycles, seed, recordDirectory, teamsWait, settle, thinkTimeout);
    }

    public ServerConfig withGame(int newCycles, long newSeed) {
        return new ServerConfig(host, port, synch, newCycles, newSeed, recordDirectory, teamsWait, settle,
                thinkTimeout);
    }

    public ServerConfig withRecordDirectory(Path directory) {
        return new ServerConfig(host, port, synch, cycles, seed, directory, teamsWait, settle, thinkTimeout);
    }

    public ServerConfig withTeamsWait(Duration wait) {
        return new ServerConfig(host, port, synch, cycles, seed, recordDirectory, wait, settle, thinkTimeout);
    }

    public ServerConfig withTimings(Duration newSettle, Duration newThinkTimeout) {
        return new ServerConfig(host, port, synch, cycles, seed, recordDirectory, teamsWait, newSettle,
                newThinkTimeout);
    }

    public ServerConfig withHost(String newHost) {
        return new ServerConfig(newHost, port, synch, cycles, seed, recordDirectory, teamsWait, settle, thinkTimeout);
    }
}
