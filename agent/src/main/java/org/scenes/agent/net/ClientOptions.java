package org.scenes.agent.net;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;

/**
 * How a team's players connect and behave on the wire.
 *
 * @param server where inits go
 * @param team the team name sent in the init
 * @param version the protocol version sent in the init, 7 to 19
 * @param goalie whether the first player inits as goalie
 * @param reconnect 0 to init; a uniform number to take that player's place with
 *                  {@code (reconnect TEAM UNUM)} instead (one player only)
 * @param connectTimeout how long a player waits for the answer to its init
 * @param silenceTimeout how long the server may stay silent before the game counts as lost
 * @param logDirectory where each player's traffic goes as a proxy log (convertible with
 *                     {@code scenes convert}); null for none
 */
public record ClientOptions(ServerAddress server, String team, int version, boolean goalie, int reconnect,
                            Duration connectTimeout, Duration silenceTimeout, Path logDirectory) {
    public static final int MIN_VERSION = 7;
    public static final int MAX_VERSION = 19;
    /**
     * The version when none is given: the one the classic recordings were made with (scene files
     * do not record it).
     */
    public static final int DEFAULT_VERSION = 9;
    public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(5);

    public ClientOptions {
        Objects.requireNonNull(server, "server");
        if (team == null || !team.matches("[A-Za-z0-9_\\-]{1,15}")) {
            throw new IllegalArgumentException("a team name is 1 to 15 letters, digits, '_' or '-', not '" + team + "'");
        }
        if (version < MIN_VERSION || version > MAX_VERSION) {
            throw new IllegalArgumentException("protocol version must be " + MIN_VERSION + " to " + MAX_VERSION
                    + ", not " + version);
        }
        if (reconnect < 0 || reconnect > 11) {
            throw new IllegalArgumentException("reconnect takes a uniform number 1 to 11, not " + reconnect);
        }
        Objects.requireNonNull(connectTimeout, "connectTimeout");
        Objects.requireNonNull(silenceTimeout, "silenceTimeout");
        if (connectTimeout.isNegative() || connectTimeout.isZero() || silenceTimeout.isNegative()
                || silenceTimeout.isZero()) {
            throw new IllegalArgumentException("timeouts must be positive");
        }
    }

    /** Defaults: version 9, no goalie, 5 s timeouts, no logs. */
    public static ClientOptions of(ServerAddress server, String team) {
        return new ClientOptions(server, team, DEFAULT_VERSION, false, 0, DEFAULT_TIMEOUT, DEFAULT_TIMEOUT, null);
    }

    public ClientOptions withVersion(int newVersion) {
        return new ClientOptions(server, team, newVersion, goalie, reconnect, connectTimeout, silenceTimeout, logDirectory);
    }

    public ClientOptions withGoalie(boolean newGoalie) {
        return new ClientOptions(server, team, version, newGoalie, reconnect, connectTimeout, silenceTimeout, logDirectory);
    }

    public ClientOptions withReconnect(int unum) {
        return new ClientOptions(server, team, version, goalie, unum, connectTimeout, silenceTimeout, logDirectory);
    }

    public ClientOptions withTimeouts(Duration connect, Duration silence) {
        return new ClientOptions(server, team, version, goalie, reconnect, connect, silence, logDirectory);
    }

    public ClientOptions withLogDirectory(Path directory) {
        return new ClientOptions(server, team, version, goalie, reconnect, connectTimeout, silenceTimeout, directory);
    }

    /** The first datagram a player sends, without its NUL. */
    String hello(boolean asGoalie) {
        if (reconnect > 0) {
            return "(reconnect " + team + " " + reconnect + ")";
        }
        return "(init " + team + " (version " + version + ")" + (asGoalie ? "(goalie)" : "") + ")";
    }
}
