package org.scenes.internal.protocol;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;
import org.scenes.api.ObjectKind;

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
public final class MessageParser extends MessageCursor {
    private final NameTable<ObjectName> objectNames = new NameTable<>();
    private final int[] argStart = new int[3];
    private final int[] argEnd = new int[3];
    private final SenseBodyReader senseBody = new SenseBodyReader(this);
    private final OccasionalMessageReader occasional = new OccasionalMessageReader(this);

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
            case "sense_body" -> noArguments() ? command(CommandType.SENSE_BODY) : senseBody.read();
            case "hear" -> occasional.hear();
            case "init" -> occasional.init();
            case "reconnect" -> occasional.reconnect();
            case "server_param", "player_param", "player_type" -> occasional.parameters(head);
            case "error", "warning", "ok", "think" -> new ServerNotice(head, restText());
            case "score" -> noArguments() ? command(CommandType.SCORE) : occasional.score();
            case "change_player_type" -> occasional.changePlayerType();
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
                known = ObjectName.of(buf, nameStart, nameEnd);
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
            case DASH -> count >= 1 && buf[argStart[0]] == '(' ? LegDashReader.read(this, count, argStart, argEnd)
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
}
