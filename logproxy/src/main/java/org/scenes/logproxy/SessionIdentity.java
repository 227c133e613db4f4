package org.scenes.logproxy;

/**
 * Who a client is, learned from the init exchange: {@code (init TEAM (version V))} or
 * {@code (reconnect TEAM UNUM)} from the client, {@code (init SIDE UNUM PLAYMODE)},
 * {@code (init SIDE ok)} (online coach) or {@code (init ok)} (trainer) from the server.
 * Mutable, owned by the log writer thread.
 */
final class SessionIdentity {
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
        String[] words = words(message);
        if (words.length >= 2 && (words[0].equals("init") || words[0].equals("reconnect"))
                && !words[1].startsWith("(")) {
            team = words[1];
            if (words[0].equals("reconnect") && words.length >= 3 && isNumber(words[2])) {
                unum = words[2];
            }
        }
    }

    /** Reads a server message; true once the identity is complete. */
    boolean fromServer(String message) {
        String[] words = words(message);
        if (words.length < 2 || !(words[0].equals("init") || words[0].equals("reconnect"))) {
            return false;
        }
        if (words[1].equals("ok")) {
            trainer = true;
        } else {
            side = words[1];
            if (words.length >= 3 && words[2].equals("ok")) {
                coach = true;
            } else if (words[0].equals("init") && words.length >= 3 && isNumber(words[2])) {
                unum = words[2];
            }
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

    /** The comment line describing the client, without the leading {@code "# "}. */
    String description() {
        if (trainer) {
            return "trainer";
        }
        return "team " + team + (coach ? " coach" : " unum " + unum) + " side " + side;
    }

    private static String safe(String name) {
        StringBuilder out = new StringBuilder(name.length());
        for (char c : name.toCharArray()) {
            out.append(Character.isLetterOrDigit(c) && c < 128 || c == '-' || c == '_' ? c : '_');
        }
        return out.toString();
    }

    private static boolean isNumber(String word) {
        return !word.isEmpty() && word.chars().allMatch(Character::isDigit);
    }

    /** The first words of an s-expression such as {@code (init l 3 before_kick_off)}. */
    private static String[] words(String message) {
        int start = message.indexOf('(');
        if (start < 0) {
            return new String[0];
        }
        int end = message.length();
        while (end > start && (message.charAt(end - 1) == ')' || message.charAt(end - 1) <= ' ')) {
            end--;
        }
        return message.substring(start + 1, end).trim().split("\\s+", 4);
    }
}
