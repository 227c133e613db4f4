package org.scenes.internal.protocol;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.Side;

/**
 * Reads, after their head, the messages that come a few times a game rather than every cycle:
 * hear, init and reconnect (either direction), server_param, player_param and player_type,
 * score and change_player_type.
 */
final class OccasionalMessageReader {
    private final MessageCursor c;

    OccasionalMessageReader(MessageCursor cursor) {
        this.c = cursor;
    }

    Hear hear() {
        int time = c.integer("the time of hear");
        c.skipSpace();
        int wordStart = c.pos;
        int wordEnd = c.atomEnd();
        String sender = c.text(wordStart, wordEnd);
        c.pos = wordEnd;
        switch (sender) {
            case "referee":
                return new Hear(time, Hear.Speaker.REFEREE, Double.NaN, 0, restOfList());
            case "self":
                return new Hear(time, Hear.Speaker.SELF, Double.NaN, 0, restOfList());
            case "coach", "online_coach_left", "online_coach_right":
                return new Hear(time, Hear.Speaker.COACH, Double.NaN, 0, restOfList());
            case "our":
                return new Hear(time, Hear.Speaker.TEAMMATE, Double.NaN, c.integer("a uniform number"), restOfList());
            case "opp":
                return new Hear(time, Hear.Speaker.OPPONENT, Double.NaN, 0, restOfList());
            default:
                break;
        }
        double direction = c.number(wordStart, wordEnd);
        if (Double.isNaN(direction)) {
            throw c.errorAt(wordStart, "hear expects referee, self, coach, our, opp or a direction");
        }
        c.skipSpace();
        int nextStart = c.pos;
        int nextEnd = c.atomEnd();
        if (c.equals(nextStart, nextEnd, "our")) {
            c.pos = nextEnd;
            int unum = c.integer("a uniform number");
            return new Hear(time, Hear.Speaker.TEAMMATE, direction, unum, restOfList());
        }
        if (c.equals(nextStart, nextEnd, "opp")) {
            c.pos = nextEnd;
            return new Hear(time, Hear.Speaker.OPPONENT, direction, 0, restOfList());
        }
        return new Hear(time, Hear.Speaker.PLAYER, direction, 0, restOfList());
    }

    /**
     * The rest of the list up to its close, as written: a quoted string without its quotes, or the
     * raw words, trailing spaces left out (what a hear says, a parameter's value).
     */
    private String restOfList() {
        c.skipSpace();
        int textStart = c.pos;
        c.skipToClose();
        int textEnd = c.pos;
        while (textEnd > textStart && MessageCursor.isSpace(c.buf[textEnd - 1])) {
            textEnd--;
        }
        if (textEnd - textStart >= 2 && c.buf[textStart] == '"' && c.buf[textEnd - 1] == '"') {
            return c.text(textStart + 1, textEnd - 1);
        }
        return c.text(textStart, textEnd);
    }

    Message init() {
        c.skipSpace();
        int firstStart = c.pos;
        int firstEnd = c.atomEnd();
        boolean trainerRequest = firstEnd == firstStart && c.buf[c.pos] == '(';
        if (firstEnd == firstStart && !trainerRequest) {
            throw c.error("init needs a team name or a side");
        }
        c.pos = firstEnd;
        c.skipSpace();
        if (c.equals(firstStart, firstEnd, "ok") && c.buf[c.pos] == ')') {
            return new InitReply("init", null, 0, null, InitReply.Role.TRAINER);
        }
        if (c.buf[c.pos] == '(' || c.buf[c.pos] == ')') {
            String team = trainerRequest ? null
                    : c.buf[firstStart] == '"' ? c.text(firstStart + 1, firstEnd - 1) : c.text(firstStart, firstEnd);
            double version = 3;
            boolean goalie = false;
            while (c.buf[c.pos] == '(') {
                c.pos++;
                c.skipSpace();
                int keyStart = c.pos;
                int keyEnd = c.atomEnd();
                c.pos = keyEnd;
                if (c.equals(keyStart, keyEnd, "version")) {
                    c.skipSpace();
                    int valueEnd = c.atomEnd();
                    version = c.number(c.pos, valueEnd);
                    if (Double.isNaN(version)) {
                        throw c.error("the version of init must be a number");
                    }
                    c.pos = valueEnd;
                } else if (c.equals(keyStart, keyEnd, "goalie")) {
                    goalie = true;
                } else {
                    throw c.errorAt(keyStart, "init accepts (version V) and (goalie)");
                }
                c.skipToClose();
                c.pos++;
                c.skipSpace();
            }
            return new InitRequest(team, version, goalie);
        }
        Side side = side(firstStart, firstEnd);
        int secondStart = c.pos;
        int secondEnd = c.atomEnd();
        if (side != null && c.equals(secondStart, secondEnd, "ok")) {
            return new InitReply("init", side, 0, null, InitReply.Role.COACH);
        }
        double unum = c.number(secondStart, secondEnd);
        if (side == null || Double.isNaN(unum) || unum != (int) unum) {
            throw c.errorAt(firstStart, "init is (init TEAM (version V)) from a client or (init SIDE UNUM PLAYMODE) from the server");
        }
        c.pos = secondEnd;
        return new InitReply("init", side, (int) unum, c.restText());
    }

    Message reconnect() {
        c.skipSpace();
        int firstStart = c.pos;
        int firstEnd = c.atomEnd();
        Side side = side(firstStart, firstEnd);
        if (side == null) {
            c.pos = firstEnd;
            c.skipSpace();
            int unumEnd = c.atomEnd();
            double unum = c.number(c.pos, unumEnd);
            if (firstEnd == firstStart || Double.isNaN(unum) || unum != (int) unum) {
                throw c.errorAt(firstStart, "reconnect is (reconnect TEAM UNUM) from a client or (reconnect SIDE PLAYMODE) from the server");
            }
            String team = c.buf[firstStart] == '"' ? c.text(firstStart + 1, firstEnd - 1) : c.text(firstStart, firstEnd);
            return new ReconnectRequest(team, (int) unum);
        }
        c.pos = firstEnd;
        return new InitReply("reconnect", side, 0, c.restText());
    }

    private Side side(int s, int e) {
        if (e - s == 1 && (c.buf[s] == 'l' || c.buf[s] == 'r')) {
            return Side.fromLetter((char) c.buf[s]);
        }
        return null;
    }

    Parameters parameters(String head) {
        Map<String, String> named = new LinkedHashMap<>();
        List<String> positional = new ArrayList<>();
        while (true) {
            c.skipSpace();
            if (c.buf[c.pos] == ')') {
                break;
            }
            if (c.buf[c.pos] == '(') {
                c.pos++;
                c.skipSpace();
                int keyStart = c.pos;
                int keyEnd = c.atomEnd();
                c.pos = keyEnd;
                named.put(c.text(keyStart, keyEnd), restOfList());
                c.pos++;
            } else {
                int valueEnd = c.atomEnd();
                positional.add(c.text(c.pos, valueEnd));
                c.pos = valueEnd;
            }
        }
        return new Parameters(head, named, positional);
    }

    Score score() {
        int time = c.integer("the time of score");
        int our = c.integer("our score");
        int their = c.integer("their score");
        return new Score(time, our, their);
    }

    ChangePlayerType changePlayerType() {
        int unum = c.integer("a uniform number");
        c.skipSpace();
        int type = c.buf[c.pos] == ')' ? -1 : c.integer("a player type");
        return new ChangePlayerType(unum, type);
    }
}
