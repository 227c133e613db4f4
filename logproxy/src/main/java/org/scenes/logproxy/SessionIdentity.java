package org.scenes.logproxy;

import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.InitRequest;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.ProtocolException;
import org.scenes.internal.protocol.ReconnectRequest;

/**
 * Who a client is, learned from the init exchange: {@code (init TEAM (version V))} or
 * {@code (reconnect TEAM UNUM)} from the client, {@code (init SIDE UNUM PLAYMODE)},
 * {@code (init SIDE ok)} (online coach) or {@code (init ok)} (trainer) from the server.
 * Mutable, owned by the log writer thread.
 */
final class SessionIdentity {
    private final MessageParser parser = new MessageParser();
    private String team;
    private String side;
    private String unum;
    private boolean coach;
    private boolean trainer;
    private boolean complete;

    boolean complete() {
        return complete;
    }

    /** Reads a client message for the team name (and number, on reconnect). */
    void fromClient(String message) {
        Message parsed = parse(message);
        if (parsed instanceof InitRequest init && init.team() != null) {
            team = init.team();
        } else if (parsed instanceof ReconnectRequest reconnect) {
            team = reconnect.team();
            unum = Integer.toString(reconnect.uniformNumber());
        }
    }

    /** Reads a server message; true once the identity is complete. */
    boolean fromServer(String message) {
        if (!(parse(message) instanceof InitReply reply)) {
            return false;
        }
        switch (reply.role()) {
            case TRAINER -> trainer = true;
            case COACH -> coach = true;
            case PLAYER -> {
                if (reply.head().equals("init")) {
                    unum = Integer.toString(reply.uniformNumber());
                }
            }
        }
        if (reply.side() != null) {
            side = String.valueOf(reply.side().letter());
        }
        complete = trainer || (team != null && (coach || unum != null));
        return complete;
    }

    /** The file name stem: {@code Team_3}, {@code Team_coach}, {@code trainer}; null if unknown. */
    String fileStem() {
        if (!complete) {
            return null;
        }
        if (trainer) {
            return "trainer";
        }
        return safe(team) + "_" + (coach ? "coach" : unum);
    }

    /** Team names longer than this are cut in file names (a name of 300 characters failed the rename). */
    static final int MAX_TEAM_IN_FILE_NAME = 64;

    /** The comment line describing the client, without the leading {@code "# "}. */
    String description() {
        if (trainer) {
            return "trainer";
        }
        return "team " + team + (coach ? " coach" : " unum " + unum) + " side " + side;
    }

    private static String safe(String name) {
        StringBuilder out = new StringBuilder(name.length());
        for (char c : name.substring(0, Math.min(name.length(), MAX_TEAM_IN_FILE_NAME)).toCharArray()) {
            out.append(Character.isLetterOrDigit(c) && c < 128 || c == '-' || c == '_' ? c : '_');
        }
        return out.toString();
    }

    /** The message, or null when it is not one the parser accepts (the identity then stays unknown). */
    private Message parse(String message) {
        try {
            return parser.parse(message);
        } catch (ProtocolException e) {
            return null;
        }
    }
}
