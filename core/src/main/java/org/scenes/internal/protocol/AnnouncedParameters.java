package org.scenes.internal.protocol;

import java.util.HashMap;
import java.util.Map;

/**
 * The parameters the server announced: its {@code server_param} and each heterogeneous
 * {@code player_type}, as named values, gathered from the lines that carry them (a game log's
 * header holds them all). One reader for everything that models the server from them.
 */
public final class AnnouncedParameters {
    private final MessageParser parser = new MessageParser();
    private final Map<String, String> server = new HashMap<>();
    private final Map<Integer, Map<String, String>> playerTypes = new HashMap<>();

    /**
     * Takes in one line; a {@code server_param} or {@code player_type} line is kept.
     *
     * @return the line's parameters when it held any ({@code player_param} too), else null
     */
    public Parameters read(String line) {
        if (!(parser.parse(line) instanceof Parameters params)) {
            return null;
        }
        if (params.head().equals("server_param")) {
            server.putAll(params.named());
        } else if (params.head().equals("player_type") && params.named().containsKey("id")) {
            playerTypes.put((int) params.number("id"), params.named());
        }
        return params;
    }

    /** The {@code server_param} values read so far. */
    public Map<String, String> server() {
        return server;
    }

    /** One {@code server_param} value, {@code fallback} when none was announced. */
    public double server(String name, double fallback) {
        return Parameters.number(server, name, fallback);
    }

    /** The values of one heterogeneous player type, null when it was not announced. */
    public Map<String, String> playerType(int id) {
        return playerTypes.get(id);
    }
}
