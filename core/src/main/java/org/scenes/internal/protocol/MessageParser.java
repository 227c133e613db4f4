package org.scenes.internal.protocol;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.scenes.api.ObjectKind;
import org.scenes.api.Side;

/**
 * Parses one soccer server message (either direction, any protocol version) into a typed
 * {@link Message}. Works directly on the bytes of the message, building no generic tree:
 * names, heads and team names are decoded once and reused, numbers are parsed in place.
 * Trailing NUL padding and whitespace are ignored.
 *
 * <p>A message that is not one balanced s-expression, or a known message of the wrong shape,
 * throws {@link ProtocolException} with the column. An unknown head is not an error: it
 * becomes {@link Unknown}. Not thread-safe (it keeps caches and scratch space); use one parser
 * per thread.
 */
public final class MessageParser {
    /** The sense_body counters, in the order of {@link SenseBody.Counts}. */
    private static final List<String> COUNTERS = List.of("kick", "dash", "turn", "say", "turn_neck", "catch",
            "move", "change_view", "change_focus");
    private static final double[] POWERS_OF_TEN = new double[23];

    static {
        POWERS_OF_TEN[0] = 1;
        for (int i = 1; i < POWERS_OF_TEN.length; i++) {
            POWERS_OF_TEN[i] = POWERS_OF_TEN[i - 1] * 10;
        }
    }

    private final NameTable<String> words = new NameTable<>();
    private final NameTable<ObjectName> objectNames = new NameTable<>();
    private final NameTable<String> dottedKeys = new NameTable<>();
    private final double[] numbers = new double[8];
    private final int[] argStart = new int[3];
    private final int[] argEnd = new int[3];
    private final int[] senseCounts = new int[COUNTERS.size()];
    private final String[] detailKeys = new String[16];
    private final String[] detailValues = new String[16];
    private int detailCount;
    private byte[] keyScratch = new byte[64];

    private byte[] buf;
    /** Where columns are counted from: the datagram or line, not the message within it. */
    private int origin;
    private int start;
    private int pos;
    private int end;

    /** A landmark, ball or upper-case object name, normalised once per distinct spelling. */
    private record ObjectName(ObjectKind kind, String name) {
    }

    /** Parses a message given as text. */
    public Message parse(CharSequence text) {
        byte[] bytes = text.toString().getBytes(StandardCharsets.UTF_8);
        return parse(bytes, 0, bytes.length);
    }

    /** Parses the message in {@code bytes[offset, offset + length)}. */
    public Message parse(byte[] bytes, int offset, int length) {
        origin = offset;
        return parseOne(bytes, offset, length);
    }

    /**
     * Parses every message of a datagram or log line that holds several, e.g. librcsc's
     * {@code (turn 0)(turn_neck 0)(done)}, handing each to {@code sink} in order. Like the server,
     * which executes the commands before a malformed one and rejects the rest, the messages before
     * a malformed one are delivered and then a {@link ProtocolException} is thrown, its column
     * counted from {@code offset}. Returns how many messages were delivered.
     */
    public int parseAll(byte[] bytes, int offset, int length, Consumer<? super Message> sink) {
        int limit = offset + length;
        int count = 0;
        int at = offset;
        while (true) {
            while (at < limit && (bytes[at] == 0 || isSpace(bytes[at]))) {
                at++;
            }
            if (at >= limit) {
                if (count == 0) {
                    origin = offset;
                    parseOne(bytes, offset, length); // throws "empty message"
                }
                return count;
            }
            origin = offset;
            // the balance check finds where this message ends: one pass over the bytes, as for one message
            Message message = parseOne(bytes, at, limit - at, true);
            at = end;
            sink.accept(message);
            count++;
        }
    }

    /**
     * The text of each message of a datagram that holds several (librcsc's {@code (turn 0)(done)}:
     * {@code (turn 0)} and {@code (done)}), split where {@link #parseAll(byte[], int, int, Consumer)}
     * finds their ends; up to a malformed one, which ends the list (it is not thrown).
     */
    public List<String> texts(CharSequence text) {
        byte[] bytes = text.toString().getBytes(StandardCharsets.UTF_8);
        List<String> texts = new ArrayList<>(4);
        int at = 0;
        while (true) {
            while (at < bytes.length && (bytes[at] == 0 || isSpace(bytes[at]))) {
                at++;
            }
            if (at >= bytes.length) {
                return texts;
            }
            origin = 0;
            try {
                parseOne(bytes, at, bytes.length - at, true);
            } catch (ProtocolException e) {
                return texts;
            }
            texts.add(new String(bytes, at, end - at, StandardCharsets.UTF_8));
            at = end;
        }
    }

    /** {@link #parseAll(byte[], int, int, Consumer)} on text, collecting the messages. */
    public List<Message> parseAll(CharSequence text) {
        byte[] bytes = text.toString().getBytes(StandardCharsets.UTF_8);
        List<Message> messages = new ArrayList<>(4);
        parseAll(bytes, 0, bytes.length, messages::add);
        return messages;
    }

    private Message parseOne(byte[] bytes, int offset, int length) {
        return parseOne(bytes, offset, length, false);
    }

    /** @param more whether more messages may follow this one (then {@code end} is left where it ends) */
    private Message parseOne(byte[] bytes, int offset, int length, boolean more) {
        buf = bytes;
        start = offset;
        end = offset + length;
        while (end > start && (buf[end - 1] == 0 || isSpace(buf[end - 1]))) {
            end--;
        }
        pos = start;
        skipSpace();
        checkBalanced(more);
        pos++;
        skipSpace();
        int headStart = pos;
        int headEnd = atomEnd();
        if (headEnd == headStart) {
            throw error("a message starts with its name, e.g. (see ...)");
        }
        String head = NameTable.string(words, buf, headStart, headEnd);
        pos = headEnd;
        return switch (head) {
            case "see" -> see();
            case "sense_body" -> noArguments() ? command(CommandType.SENSE_BODY) : senseBody();
            case "hear" -> hear();
            case "init" -> init();
            case "reconnect" -> reconnect();
            case "server_param", "player_param", "player_type" -> parameters(head);
            case "error", "warning", "ok", "think" -> new ServerNotice(head, restText());
            case "score" -> noArguments() ? command(CommandType.SCORE) : score();
            case "change_player_type" -> changePlayerType();
            default -> {
                CommandType type = CommandType.fromKey(head);
                yield type != null ? command(type) : new Unknown(head, text(start, end));
            }
        };
    }

    // ---- structure -------------------------------------------------------------------------

    /**
     * One pass over the message: one list, parentheses balanced outside strings, nothing after it
     * unless {@code more} messages may follow. Leaves {@code end} just after the closing ')'.
     */
    private void checkBalanced(boolean more) {
        if (pos >= end) {
            throw error("empty message");
        }
        if (buf[pos] != '(') {
            throw error("a message starts with '('");
        }
        int depth = 0;
        for (int i = pos; i < end; i++) {
            byte c = buf[i];
            if (c == '(') {
                depth++;
            } else if (c == ')') {
                depth--;
                if (depth == 0) {
                    for (int j = i + 1; j < end && !more; j++) {
                        if (!isSpace(buf[j]) && buf[j] != 0) {
                            throw errorAt(j, "unexpected text after the message's closing ')'"
                                    + " (a datagram with several messages is read with parseAll)");
                        }
                    }
                    end = i + 1;
                    return;
                }
            } else if (c == '"' && startsString(i)) {
                int close = i + 1;
                while (close < end && buf[close] != '"') {
                    close++;
                }
                if (close >= end) {
                    throw errorAt(i, "string not closed");
                }
                i = close;
            }
        }
        throw errorAt(end, depth + " unclosed '(' at the end of the message (not a balanced s-expression)");
    }

    private boolean noArguments() {
        skipSpace();
        return buf[pos] == ')';
    }

    // ---- see --------------------------------------------------------------------------------

    private See see() {
        int time = integer("the time of see");
        List<VisualObject> objects = new ArrayList<>(32);
        List<String> leftovers = null;
        while (true) {
            skipSpace();
            if (buf[pos] == ')') {
                break;
            }
            int elementStart = pos;
            VisualObject object = buf[pos] == '(' ? visualObject() : null;
            if (object == null) {
                pos = elementStart;
                skipElement();
                if (leftovers == null) {
                    leftovers = new ArrayList<>(2);
                }
                leftovers.add(text(elementStart, pos));
            } else if (objects.size() == MAX_SEEN_OBJECTS) {
                throw error("a see of more than " + MAX_SEEN_OBJECTS + " objects (the server lists fewer than 100)");
            } else {
                objects.add(object);
            }
        }
        return new See(time, objects, leftovers == null ? List.of() : leftovers);
    }

    /** {@code ((NAME...) NUMBERS... [t|k])}, or null when the element has another shape. */
    private VisualObject visualObject() {
        pos++;
        skipSpace();
        if (buf[pos] != '(') {
            return null;
        }
        pos++;
        skipSpace();
        int nameStart = pos;
        int firstEnd = atomEnd();
        ObjectKind kind;
        String name;
        String team = "";
        int unum = 0;
        boolean goalie = false;
        if (isPlayerWord(nameStart, firstEnd)) {
            kind = ObjectKind.PLAYER;
            boolean upper = buf[nameStart] == 'P';
            name = upper ? "P" : "p";
            pos = firstEnd;
            skipSpace();
            if (!upper && buf[pos] != ')') {
                int teamStart = pos;
                int teamEnd = atomEnd();
                team = buf[teamStart] == '"'
                        ? NameTable.string(words, buf, teamStart + 1, teamEnd - 1)
                        : NameTable.string(words, buf, teamStart, teamEnd);
                pos = teamEnd;
                skipSpace();
                if (buf[pos] != ')') {
                    int unumEnd = atomEnd();
                    double number = number(pos, unumEnd);
                    if (Double.isNaN(number) || number != (int) number) {
                        return null;
                    }
                    unum = (int) number;
                    pos = unumEnd;
                    skipSpace();
                    if (buf[pos] != ')') {
                        int markEnd = atomEnd();
                        if (!equals(pos, markEnd, "goalie")) {
                            return null;
                        }
                        goalie = true;
                        pos = markEnd;
                        skipSpace();
                    }
                }
            }
            if (buf[pos] != ')') {
                return null;
            }
        } else {
            int nameEnd = pos;
            // a quote ends the name too: no landmark's name has one, and the balance check read
            // a string from it, so a name read on past it could run off the message's end
            while (nameEnd < end && buf[nameEnd] != ')' && buf[nameEnd] != '(' && buf[nameEnd] != '"') {
                nameEnd++;
            }
            if (nameEnd >= end || buf[nameEnd] != ')') {
                return null;
            }
            ObjectName known = objectNames.get(buf, nameStart, nameEnd);
            if (known == null) {
                known = objectName(nameStart, nameEnd);
                if (known == null) {
                    return null;
                }
                objectNames.put(buf, nameStart, nameEnd, known);
            }
            kind = known.kind();
            name = known.name();
            pos = nameEnd;
        }
        pos++;
        int count = 0;
        char mark = ' ';
        while (true) {
            skipSpace();
            if (buf[pos] == ')') {
                break;
            }
            if (buf[pos] == '(' || buf[pos] == '"') {
                return null;
            }
            int tokenEnd = atomEnd();
            if (tokenEnd == pos + 1 && (buf[pos] == 't' || buf[pos] == 'k') && kind == ObjectKind.PLAYER) {
                mark = (char) buf[pos];
            } else {
                double value = number(pos, tokenEnd);
                if (Double.isNaN(value) && looksLikeNumber(pos, tokenEnd)) {
                    // 1e999, inf, nan: a known object with a broken value is a broken message, not
                    // an unknown element to pass over (that would drop the ball without a word)
                    throw error("(" + name + "): '" + text(pos, tokenEnd) + "' is not a finite number");
                }
                if (Double.isNaN(value) || count == numbers.length || mark != ' ') {
                    return null;
                }
                numbers[count++] = value;
            }
            pos = tokenEnd;
        }
        pos++;
        return fields(kind, name, team, unum, goalie, count, mark);
    }

    /**
     * Assigns the numbers by their count. Players: {@code dir} (low quality), {@code dist dir},
     * {@code dist dir point}, {@code dist dir dchg dirchg [body [head [point]]]}; other objects:
     * {@code dir}, {@code dist dir}, {@code dist dir dchg dirchg}.
     */
    private VisualObject fields(ObjectKind kind, String name, String team, int unum, boolean goalie,
                                int count, char mark) {
        double nan = Double.NaN;
        double dist = nan;
        double dir = nan;
        double distChange = nan;
        double dirChange = nan;
        double body = nan;
        double head = nan;
        double point = nan;
        boolean player = kind == ObjectKind.PLAYER;
        switch (count) {
            case 1 -> dir = numbers[0];
            case 2 -> {
                dist = numbers[0];
                dir = numbers[1];
            }
            case 3 -> {
                if (!player) {
                    return null;
                }
                dist = numbers[0];
                dir = numbers[1];
                point = numbers[2];
            }
            case 4, 5, 6, 7 -> {
                if (!player && count != 4) {
                    return null;
                }
                dist = numbers[0];
                dir = numbers[1];
                distChange = numbers[2];
                dirChange = numbers[3];
                body = count > 4 ? numbers[4] : nan;
                head = count > 5 ? numbers[5] : nan;
                point = count > 6 ? numbers[6] : nan;
            }
            default -> {
                return null;
            }
        }
        if (dist < 0 || dist > MAX_DISTANCE || Math.abs(dir) > 180 || Math.abs(body) > 180 || Math.abs(head) > 180
                || Math.abs(point) > 180) {
            throw error("(" + name + "): a distance below 0 or above " + (int) MAX_DISTANCE
                    + " m, or a direction beyond 180 degrees: " + Arrays.toString(Arrays.copyOf(numbers, count)));
        }
        return new VisualObject(kind, name, team, unum, goalie, dist, dir, distChange, dirChange,
                body, head, point, mark);
    }

    /** The most objects a see may list: matching costs grow with the square of the count. */
    private static final int MAX_SEEN_OBJECTS = 256;
    /** Metres: no object on or around the pitch is seen farther (its diagonal is about 130 m). */
    private static final double MAX_DISTANCE = 1000;

    private boolean isPlayerWord(int s, int e) {
        int length = e - s;
        return (length == 1 && (buf[s] == 'p' || buf[s] == 'P'))
                || equals(s, e, "player") || equals(s, e, "Player");
    }

    /** Normalises a non-player name: long words become short letters, single spaces between parts. */
    private ObjectName objectName(int nameStart, int nameEnd) {
        StringBuilder name = new StringBuilder(12);
        ObjectKind kind = null;
        int p = nameStart;
        boolean first = true;
        boolean upper = false;
        while (p < nameEnd) {
            while (p < nameEnd && isSpace(buf[p])) {
                p++;
            }
            int wordStart = p;
            while (p < nameEnd && !isSpace(buf[p])) {
                p++;
            }
            if (wordStart == p) {
                break;
            }
            String word = new String(buf, wordStart, p - wordStart, StandardCharsets.UTF_8);
            if (first) {
                String letter = switch (word) {
                    case "b", "ball" -> "b";
                    case "B", "Ball" -> "B";
                    case "g", "goal" -> "g";
                    case "G", "Goal" -> "G";
                    case "f", "flag" -> "f";
                    case "F", "Flag" -> "F";
                    case "l", "line" -> "l";
                    default -> null;
                };
                if (letter == null) {
                    return null;
                }
                upper = Character.isUpperCase(letter.charAt(0));
                kind = switch (Character.toLowerCase(letter.charAt(0))) {
                    case 'b' -> ObjectKind.BALL;
                    case 'g' -> ObjectKind.GOAL;
                    case 'f' -> ObjectKind.FLAG;
                    default -> ObjectKind.LINE;
                };
                name.append(letter);
                first = false;
            } else {
                if (upper || kind == ObjectKind.BALL) {
                    return null;
                }
                name.append(' ').append(word);
            }
        }
        return kind == null ? null : new ObjectName(kind, name.toString());
    }

    // ---- sense_body -------------------------------------------------------------------------

    private SenseBody senseBody() {
        int time = integer("the time of sense_body");
        String quality = "";
        String width = "";
        double nan = Double.NaN;
        double stamina = nan;
        double effort = nan;
        double capacity = nan;
        double speed = nan;
        double speedDirection = nan;
        double headAngle = nan;
        int[] counts = senseCounts;
        Arrays.fill(counts, -1);
        detailCount = 0;
        List<String> leftovers = List.of();
        while (true) {
            skipSpace();
            if (buf[pos] == ')') {
                break;
            }
            int elementStart = pos;
            boolean understood = buf[pos] == '(';
            if (understood) {
                pos++;
                skipSpace();
                int keyStart = pos;
                int keyEnd = atomEnd();
                String key = NameTable.string(words, buf, keyStart, keyEnd);
                pos = keyEnd;
                int counter = COUNTERS.indexOf(key);
                if (counter >= 0) {
                    understood = numbers() == 1 && numbers[0] == (int) numbers[0] && numbers[0] >= 0;
                    if (understood) {
                        counts[counter] = (int) numbers[0];
                    }
                } else {
                    switch (key) {
                        case "view_mode" -> {
                            quality = word();
                            width = word();
                        }
                        case "stamina" -> {
                            int n = numbers();
                            stamina = n > 0 ? numbers[0] : nan;
                            effort = n > 1 ? numbers[1] : nan;
                            capacity = n > 2 ? numbers[2] : nan;
                            understood = n >= 2 && n <= 3;
                        }
                        case "speed" -> {
                            int n = numbers();
                            speed = n > 0 ? numbers[0] : nan;
                            speedDirection = n > 1 ? numbers[1] : nan;
                            understood = n >= 1 && n <= 2;
                        }
                        case "head_angle" -> {
                            understood = numbers() == 1;
                            headAngle = numbers[0];
                        }
                        case "arm", "focus", "tackle", "foul" -> understood = subfields(keyStart);
                        case "collision", "focus_point" -> {
                            skipSpace();
                            int valueStart = pos;
                            skipToClose();
                            detail(key, valueStart, pos);
                        }
                        default -> understood = false;
                    }
                }
                skipSpace();
                understood &= buf[pos] == ')';
            }
            if (understood) {
                pos++;
            } else {
                pos = elementStart;
                skipElement();
                if (leftovers.isEmpty()) {
                    leftovers = new ArrayList<>(2);
                }
                leftovers.add(text(elementStart, pos));
            }
        }
        boolean anyCount = false;
        for (int count : counts) {
            anyCount |= count >= 0;
        }
        SenseBody.Counts typedCounts = !anyCount ? SenseBody.Counts.NONE
                : new SenseBody.Counts(counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], counts[6],
                        counts[7], counts[8]);
        return new SenseBody(time, quality, width, stamina, effort, capacity, speed, speedDirection,
                headAngle, typedCounts, details(), leftovers);
    }

    /**
     * {@code (arm (movable 0) (expires 0) (target 0 0) (count 0))}: each part as {@code arm.movable}...
     * Keys are cached by the bytes from the parent's name to the part's name, values by their bytes,
     * so a sense_body allocates little beyond its record.
     */
    private boolean subfields(int parentStart) {
        while (true) {
            skipSpace();
            if (buf[pos] == ')') {
                return true;
            }
            if (buf[pos] != '(') {
                return false;
            }
            pos++;
            skipSpace();
            int keyStart = pos;
            int keyEnd = atomEnd();
            String key = dottedKey(parentStart, keyStart, keyEnd);
            pos = keyEnd;
            skipSpace();
            int valueStart = pos;
            skipToClose();
            detail(key, valueStart, pos);
            pos++;
        }
    }

    /** "arm" and "target" become the cached "arm.target" (cached by its bytes, built once). */
    private String dottedKey(int parentStart, int keyStart, int keyEnd) {
        int parentEnd = parentStart;
        while (parentEnd < end && !isSpace(buf[parentEnd]) && buf[parentEnd] != '(' && buf[parentEnd] != ')') {
            parentEnd++;
        }
        int length = (parentEnd - parentStart) + 1 + (keyEnd - keyStart);
        if (keyScratch.length < length) {
            keyScratch = new byte[length * 2];
        }
        System.arraycopy(buf, parentStart, keyScratch, 0, parentEnd - parentStart);
        keyScratch[parentEnd - parentStart] = '.';
        System.arraycopy(buf, keyStart, keyScratch, parentEnd - parentStart + 1, keyEnd - keyStart);
        return NameTable.string(dottedKeys, keyScratch, 0, length);
    }

    private void detail(String key, int valueStart, int valueEnd) {
        while (valueEnd > valueStart && isSpace(buf[valueEnd - 1])) {
            valueEnd--;
        }
        for (int i = 0; i < detailCount; i++) {
            if (detailKeys[i].equals(key)) { // sent twice: the last one counts
                detailValues[i] = NameTable.string(words, buf, valueStart, valueEnd);
                return;
            }
        }
        if (detailCount < detailKeys.length) {
            detailKeys[detailCount] = key;
            detailValues[detailCount] = NameTable.string(words, buf, valueStart, valueEnd);
            detailCount++;
        }
    }

    @SuppressWarnings("unchecked")
    private Map<String, String> details() {
        if (detailCount == 0) {
            return Map.of();
        }
        Map.Entry<String, String>[] entries = new Map.Entry[detailCount];
        for (int i = 0; i < detailCount; i++) {
            entries[i] = Map.entry(detailKeys[i], detailValues[i]);
        }
        return Map.ofEntries(entries);
    }

    // ---- hear -------------------------------------------------------------------------------

    private Hear hear() {
        int time = integer("the time of hear");
        skipSpace();
        int wordStart = pos;
        int wordEnd = atomEnd();
        String sender = text(wordStart, wordEnd);
        pos = wordEnd;
        switch (sender) {
            case "referee":
                return new Hear(time, Hear.Speaker.REFEREE, Double.NaN, 0, restMessage());
            case "self":
                return new Hear(time, Hear.Speaker.SELF, Double.NaN, 0, restMessage());
            case "coach", "online_coach_left", "online_coach_right":
                return new Hear(time, Hear.Speaker.COACH, Double.NaN, 0, restMessage());
            case "our":
                return new Hear(time, Hear.Speaker.TEAMMATE, Double.NaN, integer("a uniform number"), restMessage());
            case "opp":
                return new Hear(time, Hear.Speaker.OPPONENT, Double.NaN, 0, restMessage());
            default:
                break;
        }
        double direction = number(wordStart, wordEnd);
        if (Double.isNaN(direction)) {
            throw errorAt(wordStart, "hear expects referee, self, coach, our, opp or a direction");
        }
        skipSpace();
        int nextStart = pos;
        int nextEnd = atomEnd();
        if (equals(nextStart, nextEnd, "our")) {
            pos = nextEnd;
            int unum = integer("a uniform number");
            return new Hear(time, Hear.Speaker.TEAMMATE, direction, unum, restMessage());
        }
        if (equals(nextStart, nextEnd, "opp")) {
            pos = nextEnd;
            return new Hear(time, Hear.Speaker.OPPONENT, direction, 0, restMessage());
        }
        return new Hear(time, Hear.Speaker.PLAYER, direction, 0, restMessage());
    }

    /** The rest of the message as said: a quoted string without its quotes, or the raw words. */
    private String restMessage() {
        skipSpace();
        int textStart = pos;
        skipToClose();
        int textEnd = pos;
        while (textEnd > textStart && isSpace(buf[textEnd - 1])) {
            textEnd--;
        }
        if (textEnd - textStart >= 2 && buf[textStart] == '"' && buf[textEnd - 1] == '"') {
            return text(textStart + 1, textEnd - 1);
        }
        return text(textStart, textEnd);
    }

    // ---- init, parameters, short server messages --------------------------------------------

    private Message init() {
        skipSpace();
        int firstStart = pos;
        int firstEnd = atomEnd();
        boolean trainerRequest = firstEnd == firstStart && buf[pos] == '(';
        if (firstEnd == firstStart && !trainerRequest) {
            throw error("init needs a team name or a side");
        }
        pos = firstEnd;
        skipSpace();
        if (equals(firstStart, firstEnd, "ok") && buf[pos] == ')') {
            return new InitReply("init", null, 0, null, InitReply.Role.TRAINER);
        }
        if (buf[pos] == '(' || buf[pos] == ')') {
            String team = trainerRequest ? null
                    : buf[firstStart] == '"' ? text(firstStart + 1, firstEnd - 1) : text(firstStart, firstEnd);
            double version = 3;
            boolean goalie = false;
            while (buf[pos] == '(') {
                pos++;
                skipSpace();
                int keyStart = pos;
                int keyEnd = atomEnd();
                pos = keyEnd;
                if (equals(keyStart, keyEnd, "version")) {
                    skipSpace();
                    int valueEnd = atomEnd();
                    version = number(pos, valueEnd);
                    if (Double.isNaN(version)) {
                        throw error("the version of init must be a number");
                    }
                    pos = valueEnd;
                } else if (equals(keyStart, keyEnd, "goalie")) {
                    goalie = true;
                } else {
                    throw errorAt(keyStart, "init accepts (version V) and (goalie)");
                }
                skipToClose();
                pos++;
                skipSpace();
            }
            return new InitRequest(team, version, goalie);
        }
        Side side = side(firstStart, firstEnd);
        int secondStart = pos;
        int secondEnd = atomEnd();
        if (side != null && equals(secondStart, secondEnd, "ok")) {
            return new InitReply("init", side, 0, null, InitReply.Role.COACH);
        }
        double unum = number(secondStart, secondEnd);
        if (side == null || Double.isNaN(unum) || unum != (int) unum) {
            throw errorAt(firstStart, "init is (init TEAM (version V)) from a client or (init SIDE UNUM PLAYMODE) from the server");
        }
        pos = secondEnd;
        return new InitReply("init", side, (int) unum, restText());
    }

    private Message reconnect() {
        skipSpace();
        int firstStart = pos;
        int firstEnd = atomEnd();
        Side side = side(firstStart, firstEnd);
        if (side == null) {
            pos = firstEnd;
            skipSpace();
            int unumEnd = atomEnd();
            double unum = number(pos, unumEnd);
            if (firstEnd == firstStart || Double.isNaN(unum) || unum != (int) unum) {
                throw errorAt(firstStart, "reconnect is (reconnect TEAM UNUM) from a client or (reconnect SIDE PLAYMODE) from the server");
            }
            String team = buf[firstStart] == '"' ? text(firstStart + 1, firstEnd - 1) : text(firstStart, firstEnd);
            return new ReconnectRequest(team, (int) unum);
        }
        pos = firstEnd;
        return new InitReply("reconnect", side, 0, restText());
    }

    private Side side(int s, int e) {
        if (e - s == 1 && (buf[s] == 'l' || buf[s] == 'r')) {
            return Side.fromLetter((char) buf[s]);
        }
        return null;
    }

    private Parameters parameters(String head) {
        Map<String, String> named = new LinkedHashMap<>();
        List<String> positional = new ArrayList<>();
        while (true) {
            skipSpace();
            if (buf[pos] == ')') {
                break;
            }
            if (buf[pos] == '(') {
                pos++;
                skipSpace();
                int keyStart = pos;
                int keyEnd = atomEnd();
                pos = keyEnd;
                skipSpace();
                int valueStart = pos;
                skipToClose();
                int valueEnd = pos;
                while (valueEnd > valueStart && isSpace(buf[valueEnd - 1])) {
                    valueEnd--;
                }
                if (valueEnd - valueStart >= 2 && buf[valueStart] == '"' && buf[valueEnd - 1] == '"') {
                    valueStart++;
                    valueEnd--;
                }
                named.put(text(keyStart, keyEnd), text(valueStart, valueEnd));
                pos++;
            } else {
                int valueEnd = atomEnd();
                positional.add(text(pos, valueEnd));
                pos = valueEnd;
            }
        }
        return new Parameters(head, named, positional);
    }

    private Score score() {
        int time = integer("the time of score");
        int our = integer("our score");
        int their = integer("their score");
        return new Score(time, our, their);
    }

    private ChangePlayerType changePlayerType() {
        int unum = integer("a uniform number");
        skipSpace();
        int type = buf[pos] == ')' ? -1 : integer("a player type");
        return new ChangePlayerType(unum, type);
    }

    // ---- player commands --------------------------------------------------------------------

    private PlayerCommand command(CommandType type) {
        int argumentsStart = pos;
        int count = arguments();
        // word arguments are decoded only for the commands that have them (not for 400k turns)
        String rest = switch (type) {
            case POINTTO, SAY, CHANGE_VIEW, ATTENTIONTO, EAR, CLANG, SENSE_BODY, SCORE, BYE, DONE, SYNCH_SEE,
                 GAUSSIAN_SEE -> text(argumentsStart, end - 1).trim();
            default -> "";
        };
        double first = count > 0 ? number(argStart[0], argEnd[0]) : Double.NaN;
        double second = count > 1 ? number(argStart[1], argEnd[1]) : Double.NaN;
        boolean firstNumber = !Double.isNaN(first);
        boolean secondNumber = !Double.isNaN(second);
        return switch (type) {
            case DASH -> count >= 1 && buf[argStart[0]] == '(' ? legDash(count)
                    : new PlayerCommand(type, first, count == 2 ? second : Double.NaN, "",
                    firstNumber && (count == 1 || (count == 2 && secondNumber)));
            case TURN, TURN_NECK, CATCH, COMPRESSION ->
                    new PlayerCommand(type, first, Double.NaN, "", count == 1 && firstNumber);
            case KICK, LONG_KICK, MOVE, CHANGE_FOCUS ->
                    new PlayerCommand(type, first, second, "", count == 2 && firstNumber && secondNumber);
            case TACKLE -> {
                String foul = count == 2 ? text(argStart[1], argEnd[1]) : "";
                yield new PlayerCommand(type, first, Double.NaN, foul,
                        firstNumber && (count == 1 || (count == 2 && PlayerCommand.foulFlag(foul) != null)));
            }
            case POINTTO -> count == 2
                    ? new PlayerCommand(type, first, second, "", firstNumber && secondNumber)
                    : new PlayerCommand(type, Double.NaN, Double.NaN, rest, count == 1 && rest.equals("off"));
            case SAY -> new PlayerCommand(type, Double.NaN, Double.NaN, unquote(rest), count >= 1);
            case CHANGE_VIEW -> new PlayerCommand(type, Double.NaN, Double.NaN, rest, count == 1 || count == 2);
            case ATTENTIONTO -> new PlayerCommand(type, count == 2 ? second : Double.NaN, Double.NaN, rest,
                    (count == 1 && rest.equals("off")) || (count == 2 && secondNumber));
            case EAR, CLANG -> new PlayerCommand(type, Double.NaN, Double.NaN, rest, count >= 1);
            case SENSE_BODY, SCORE, BYE, DONE, SYNCH_SEE, GAUSSIAN_SEE ->
                    new PlayerCommand(type, Double.NaN, Double.NaN, rest, count == 0);
        };
    }

    /**
     * rcssserver 19's two-leg dash, {@code (dash (l POWER DIR) (r POWER DIR))}, either leg alone or
     * both in any order. Kept in {@code text} as the server got it (single spaces); {@code first} and
     * {@code second} are the mean power and direction of the legs sent, the plain dash closest to it.
     */
    private PlayerCommand legDash(int count) {
        boolean wellFormed = count == 1 || count == 2;
        double powerSum = 0;
        double directionSum = 0;
        int legs = 0;
        boolean left = false;
        boolean right = false;
        StringBuilder text = new StringBuilder(24);
        int arguments = Math.min(count, argStart.length);
        int[] starts = Arrays.copyOf(argStart, arguments);
        int[] ends = Arrays.copyOf(argEnd, arguments);
        int saved = pos;
        for (int i = 0; i < arguments && wellFormed; i++) {
            if (buf[starts[i]] != '(') {
                wellFormed = false;
                break;
            }
            pos = starts[i] + 1;
            String leg = word();
            boolean isLeft = leg.equals("l");
            if (!(isLeft || leg.equals("r")) || (isLeft ? left : right)) {
                wellFormed = false;
                break;
            }
            if (isLeft) {
                left = true;
            } else {
                right = true;
            }
            if (text.length() > 0) {
                text.append(' ');
            }
            text.append('(').append(leg);
            int listEnd = ends[i] - 1;
            int found = 0;
            double power = Double.NaN;
            double direction = Double.NaN;
            while (true) {
                skipSpace();
                if (pos >= listEnd) {
                    break;
                }
                int tokenEnd = atomEnd();
                double value = number(pos, tokenEnd);
                if (Double.isNaN(value) || found == 2) {
                    found = -1;
                    break;
                }
                text.append(' ').append(text(pos, tokenEnd));
                pos = tokenEnd;
                if (found == 0) {
                    power = value;
                } else {
                    direction = value;
                }
                found++;
            }
            if (found != 2) {
                wellFormed = false;
                break;
            }
            text.append(')');
            powerSum += power;
            directionSum += direction;
            legs++;
        }
        pos = saved;
        if (!wellFormed || legs == 0) {
            return new PlayerCommand(CommandType.DASH, Double.NaN, Double.NaN, "", false);
        }
        return new PlayerCommand(CommandType.DASH, powerSum / legs, directionSum / legs, text.toString(), true);
    }

    /** Finds up to three top-level arguments (atoms, strings or lists); returns how many there are. */
    private int arguments() {
        int count = 0;
        while (true) {
            skipSpace();
            if (buf[pos] == ')') {
                return count;
            }
            int elementStart = pos;
            skipElement();
            if (count < argStart.length) {
                argStart[count] = elementStart;
                argEnd[count] = pos;
            }
            count++;
        }
    }

    private static String unquote(String text) {
        if (text.length() >= 2 && text.charAt(0) == '"' && text.charAt(text.length() - 1) == '"') {
            return text.substring(1, text.length() - 1);
        }
        return text;
    }

    // ---- tokens -----------------------------------------------------------------------------

    private void skipSpace() {
        while (pos < end && isSpace(buf[pos])) {
            pos++;
        }
    }

    private static boolean isSpace(byte c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    }

    /** End of the atom or string at {@code pos}. */
    /**
     * Whether the quote at {@code i} opens a string: only at the start of an atom. A quote inside
     * an atom ({@code p"x(}) is an ordinary byte, as {@link #atomEnd()} reads it; the balance check
     * and the skipping must agree with it, or parentheses one skips the other counts (found by fuzzing).
     */
    private boolean startsString(int i) {
        if (i == start) {
            return true;
        }
        byte before = buf[i - 1];
        return before == '(' || before == ')' || isSpace(before);
    }

    private int atomEnd() {
        int p = pos;
        if (p < end && buf[p] == '"') {
            p++;
            while (p < end && buf[p] != '"') {
                p++;
            }
            return Math.min(p + 1, end);
        }
        while (p < end) {
            byte c = buf[p];
            if (c == '(' || c == ')' || isSpace(c)) {
                break;
            }
            p++;
        }
        return p;
    }

    /** Moves past one atom, string or balanced list. */
    private void skipElement() {
        if (buf[pos] != '(') {
            pos = Math.max(atomEnd(), pos + 1);
            return;
        }
        pos++;
        skipToClose();
        pos++;
    }

    /** Moves to the ')' closing the current list (balance was checked before). */
    private void skipToClose() {
        int depth = 0;
        while (pos < end) {
            byte c = buf[pos];
            if (c == '"' && startsString(pos)) {
                pos = atomEnd();
                continue;
            }
            if (c == '(') {
                depth++;
            } else if (c == ')') {
                if (depth == 0) {
                    return;
                }
                depth--;
            }
            pos++;
        }
    }

    /** Reads numbers until the list closes; returns how many (more than fit counts as too many). */
    private int numbers() {
        int count = 0;
        while (true) {
            skipSpace();
            if (buf[pos] == ')' || buf[pos] == '(') {
                return count;
            }
            int tokenEnd = atomEnd();
            double value = number(pos, tokenEnd);
            pos = tokenEnd;
            if (Double.isNaN(value) || count == numbers.length) {
                return -1;
            }
            numbers[count++] = value;
        }
    }

    private String word() {
        skipSpace();
        int wordStart = pos;
        pos = atomEnd();
        return NameTable.string(words, buf, wordStart, pos);
    }

    private int integer(String what) {
        skipSpace();
        int tokenEnd = atomEnd();
        double value = number(pos, tokenEnd);
        if (Double.isNaN(value) || value != Math.rint(value) || Math.abs(value) > Integer.MAX_VALUE) {
            throw error("expected " + what + " (an integer) but found '" + text(pos, tokenEnd) + "'");
        }
        pos = tokenEnd;
        return (int) value;
    }

    /** The words after the head up to the closing parenthesis. */
    private String restText() {
        return text(pos, end - 1).trim();
    }

    /**
     * Parses a decimal number in place; {@code NaN} when the token is not a number. Up to 15
     * significant digits and 22 fraction digits the result is exact (one correctly rounded
     * division); anything longer or with an exponent goes through {@link Double#parseDouble}.
     */
    private double number(int s, int e) {
        if (s >= e) {
            return Double.NaN;
        }
        int i = s;
        boolean negative = false;
        if (buf[i] == '-' || buf[i] == '+') {
            negative = buf[i] == '-';
            i++;
        }
        long mantissa = 0;
        int digits = 0;
        int fraction = 0;
        boolean dot = false;
        for (; i < e; i++) {
            byte c = buf[i];
            if (c >= '0' && c <= '9') {
                if (digits < 18) {
                    mantissa = mantissa * 10 + (c - '0');
                }
                digits++;
                if (dot) {
                    fraction++;
                }
            } else if (c == '.' && !dot) {
                dot = true;
            } else if (c == 'e' || c == 'E') {
                return slowNumber(s, e);
            } else {
                return Double.NaN;
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        if (digits >= 18 || mantissa >= (1L << 53) || fraction >= POWERS_OF_TEN.length) {
            return slowNumber(s, e);
        }
        double value = fraction == 0 ? mantissa : mantissa / POWERS_OF_TEN[fraction];
        return negative ? -value : value;
    }

    /** NaN also for what overflows to infinity (1e999): the protocol has no infinite values. */
    private double slowNumber(int s, int e) {
        try {
            double value = Double.parseDouble(text(s, e));
            return Double.isFinite(value) ? value : Double.NaN;
        } catch (NumberFormatException ex) {
            return Double.NaN;
        }
    }

    /** A token meant as a number: a digit, sign or dot first, or a spelling of infinity or NaN. */
    private boolean looksLikeNumber(int s, int e) {
        byte first = buf[s];
        if ((first >= '0' && first <= '9') || first == '-' || first == '+' || first == '.') {
            return true;
        }
        String word = text(s, e).toLowerCase(java.util.Locale.ROOT);
        return word.equals("nan") || word.startsWith("inf");
    }

    private boolean equals(int s, int e, String literal) {
        if (e - s != literal.length()) {
            return false;
        }
        for (int i = 0; i < literal.length(); i++) {
            if (buf[s + i] != literal.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    private String text(int s, int e) {
        return new String(buf, s, Math.max(0, e - s), StandardCharsets.UTF_8);
    }

    private ProtocolException error(String message) {
        return errorAt(pos, message);
    }

    private ProtocolException errorAt(int at, String message) {
        return new ProtocolException(at - origin + 1, message);
    }
}
