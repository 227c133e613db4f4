package org.scenes.simulator.server;

import org.scenes.internal.protocol.InitRequest;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.ProtocolException;

/**
 * What a new client asks on the init port, read with core's parser and judged with rcssserver's
 * rules: an init ({@code (init TEAM [(version V)] [(goalie)])}, team names of 1 to 15 letters,
 * digits, '-', '+' or '_'), a reconnect ({@code (reconnect TEAM UNUM)}), or the error the server
 * answers.
 *
 * @param unum the uniform number of a reconnect, 0 for an init
 * @param error the server's answer when the request is refused, else null
 */
record Admission(String team, int version, boolean goalie, int unum, String error) {
    private static final int MAX_TEAM_NAME = 15;

    static Admission refused(String answer) {
        return new Admission(null, 0, false, 0, answer);
    }

    static Admission read(MessageParser parser, String text) {
        if (text.startsWith("(reconnect ")) {
            return reconnect(text);
        }
        if (!text.startsWith("(init ")) {
            return refused("(error unknown_command)");
        }
        String afterHead = text.substring("(init ".length()).strip();
        if (afterHead.isEmpty() || afterHead.charAt(0) == '(' || afterHead.charAt(0) == ')') {
            return refused("(error illegal_teamname)");
        }
        Message message;
        try {
            message = parser.parse(text);
        } catch (ProtocolException e) {
            return refused("(error illegal_command_form)");
        }
        if (!(message instanceof InitRequest init)) {
            return refused("(error illegal_command_form)");
        }
        String team = init.team();
        if (team.isEmpty() || !isTeamCharacter(team.charAt(0))) {
            return refused("(error illegal_teamname)");
        }
        if (team.length() > MAX_TEAM_NAME || !team.chars().allMatch(c -> isTeamCharacter((char) c))) {
            return refused("(error illegal_teamname_or_too_long_teamname)");
        }
        if (init.version() < 1 || init.version() > 1000) {
            return refused("(error illegal_command_form)");
        }
        return new Admission(team, (int) Math.floor(init.version()), init.goalie(), 0, null);
    }

    /** {@code (reconnect TEAM UNUM)}: the team and the uniform number to take over. */
    private static Admission reconnect(String text) {
        String inner = text.strip();
        if (!inner.endsWith(")")) {
            return refused("(error illegal_command_form)");
        }
        String[] words = inner.substring("(reconnect ".length(), inner.length() - 1).trim().split("\\s+");
        if (words.length != 2 || !words[1].matches("\\d{1,2}")) {
            return refused("(error illegal_command_form)");
        }
        return new Admission(words[0], 0, false, Integer.parseInt(words[1]), null);
    }

    private static boolean isTeamCharacter(char c) {
        return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c >= '0' && c <= '9' || c == '-' || c == '+'
                || c == '_';
    }
}
