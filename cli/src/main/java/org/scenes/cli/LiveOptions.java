package org.scenes.cli;

import java.nio.file.Path;
import java.time.Duration;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.ServerAddress;
import picocli.CommandLine.Option;

/** How a team joins a soccer server over UDP: the options {@code play --server} and {@code team} share. */
final class LiveOptions {
    @Option(names = "--server", paramLabel = "HOST:PORT",
            description = "Play on the soccer server taking player inits at HOST:PORT (rcssserver: 6000) over UDP.")
    String server;

    @Option(names = "--team", paramLabel = "NAME", description = "The team name sent in each init.")
    String team;

    @Option(names = "--goalie", description = "The first player inits as goalie.")
    boolean goalie;

    @Option(names = "--version", paramLabel = "V", defaultValue = "9",
            description = "Protocol version sent in the init, 7 to 19 (scene files do not record theirs; the classic"
                    + " recordings are version 9). Default: ${DEFAULT-VALUE}.")
    int version;

    @Option(names = "--reconnect", paramLabel = "UNUM",
            description = "Take the place of player UNUM of the team with (reconnect TEAM UNUM); needs --players 1.")
    int reconnect;

    @Option(names = "--timeout", paramLabel = "SECONDS", defaultValue = "5",
            description = "Seconds to wait for the answer to the init, and for any message during the game, before"
                    + " giving up. Default: ${DEFAULT-VALUE}.")
    double timeout;

    @Option(names = "--log-dir", paramLabel = "DIR",
            description = "Write each player's traffic as a proxy log (TEAM_UNUM.log), convertible with 'scenes convert'.")
    Path logDirectory;

    @Option(names = "--json", description = "Print the players' reports as one JSON array instead of a table.")
    boolean json;

    /** The client options; a usage error names the option that is wrong. */
    ClientOptions clientOptions(String defaultTeam) {
        ServerAddress address;
        try {
            address = ServerAddress.parse(server);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--server: " + e.getMessage());
        }
        if (!(timeout > 0) || timeout > 3600) {
            throw new UsageException("--timeout: give seconds between 0 and 3600, not " + timeout);
        }
        Duration wait = Duration.ofMillis(Math.round(timeout * 1000));
        try {
            return new ClientOptions(address, team == null ? defaultTeam : team, version, goalie, reconnect, wait, wait,
                    logDirectory);
        } catch (IllegalArgumentException e) {
            String option = e.getMessage().startsWith("protocol") ? "--version" : e.getMessage().startsWith("a team")
                    ? "--team" : "--reconnect";
            throw new UsageException(option + ": " + e.getMessage());
        }
    }
}
