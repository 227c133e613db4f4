package org.scenes.internal.convert;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Tells an online coach's traffic from a player's by messages only a coach exchanges, so that a
 * coach's log is named as such instead of yielding thousands of malformed or unknown lines.
 */
final class CoachLog {
    /** Message starts only a coach's traffic holds, with what they are. */
    private static final String[][] MARKS = {
        {"(see_global ", "the server's see_global"},
        {"(init l ok)", "the server's coach init reply (init l ok)"},
        {"(init r ok)", "the server's coach init reply (init r ok)"},
        {"(eye ", "the coach command eye"},
        {"(look)", "the coach command look"},
        {"(team_names)", "the coach command team_names"},
        {"(ok look ", "the server's answer to look"},
        {"(ok eye ", "the server's answer to eye"},
        {"(ok team_names ", "the server's answer to team_names"},
    };

    /** The marks' bytes, made once: every {@code (see} line of a log is checked. */
    private static final byte[][] PREFIXES = new byte[MARKS.length][];

    static {
        for (int i = 0; i < MARKS.length; i++) {
            PREFIXES[i] = MARKS[i][0].getBytes(StandardCharsets.US_ASCII);
        }
    }

    private CoachLog() {
    }

    /** What in this message shows a coach's log, or null when nothing does. */
    static String evidence(byte[] bytes, int offset, int length) {
        int at = offset;
        int end = offset + length;
        while (at < end && (bytes[at] == ' ' || bytes[at] == '\t')) {
            at++;
        }
        // cheap first: every mark starts "(s", "(i", "(e", "(l", "(t" or "(o"
        if (end - at < 6 || bytes[at] != '(') {
            return null;
        }
        byte second = bytes[at + 1];
        if (second != 's' && second != 'i' && second != 'e' && second != 'l' && second != 't' && second != 'o') {
            return null;
        }
        for (int i = 0; i < MARKS.length; i++) {
            byte[] prefix = PREFIXES[i];
            if (end - at >= prefix.length && Arrays.equals(bytes, at, at + prefix.length, prefix, 0, prefix.length)) {
                return MARKS[i][1];
            }
        }
        return null;
    }
}
