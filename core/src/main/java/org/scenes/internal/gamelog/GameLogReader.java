package org.scenes.internal.gamelog;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PushbackInputStream;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.scenes.api.Side;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.files.JsonErrors;

/**
 * Reads a server game log ({@code .rcg}) into {@link GameFrame}s, one per {@code show}, as a
 * stream: the text formats of versions 4, 5 and 6 ({@code ULG4} to {@code ULG6}) and the JSON
 * form rcssserver 19 writes with {@code game_log_version -1}; gzipped or not. A frame's play
 * mode, team names and score are those of the latest {@code playmode} and {@code team}
 * lines; parameter, message, drawing and team-graphic lines are skipped. A player's capacity
 * is NaN where the log has none or writes it as negative (unlimited). Errors name the file
 * and line.
 */
public final class GameLogReader {
    /** Play mode names by their number, as a monitor's {@code (pm N)} gives them. */
    private static final List<String> PLAY_MODES = List.of("", "before_kick_off", "time_over", "play_on",
            "kick_off_l", "kick_off_r", "kick_in_l", "kick_in_r", "free_kick_l", "free_kick_r", "corner_kick_l",
            "corner_kick_r", "goal_kick_l", "goal_kick_r", "goal_l", "goal_r", "drop_ball", "offside_l",
            "offside_r", "penalty_kick_l", "penalty_kick_r", "first_half_over", "pause", "human_judge",
            "foul_charge_l", "foul_charge_r", "foul_push_l", "foul_push_r", "foul_multiple_attack_l",
            "foul_multiple_attack_r", "foul_ballout_l", "foul_ballout_r", "back_pass_l", "back_pass_r",
            "free_kick_fault_l", "free_kick_fault_r", "catch_fault_l", "catch_fault_r", "indirect_free_kick_l",
            "indirect_free_kick_r", "penalty_setup_l", "penalty_setup_r", "penalty_ready_l", "penalty_ready_r",
            "penalty_taken_l", "penalty_taken_r", "penalty_miss_l", "penalty_miss_r", "penalty_score_l",
            "penalty_score_r", "illegal_defense_l", "illegal_defense_r", "penalty_onfield_l",
            "penalty_onfield_r", "penalty_foul_l", "penalty_foul_r", "goalie_catch_ball_l",
            "goalie_catch_ball_r");

    /** 10^0 to 10^15, all exact doubles. */
    private static final double[] POWERS_OF_TEN = new double[16];

    static {
        POWERS_OF_TEN[0] = 1;
        for (int i = 1; i < POWERS_OF_TEN.length; i++) {
            POWERS_OF_TEN[i] = POWERS_OF_TEN[i - 1] * 10;
        }
    }

    private final Path file;
    private final Consumer<GameFrame> frames;
    private final Consumer<String> parameters;
    private String playMode = "";
    private String leftTeam = "";
    private String rightTeam = "";
    private int scoreLeft;
    private int scoreRight;

    private GameLogReader(Path file, Consumer<GameFrame> frames, Consumer<String> parameters) {
        this.file = file;
        this.frames = frames;
        this.parameters = parameters;
    }

    /** Reads every frame of the log. */
    public static List<GameFrame> readAll(Path file) throws IOException {
        List<GameFrame> all = new ArrayList<>();
        forEach(file, all::add);
        return all;
    }

    /** Hands each frame to {@code action} as it is read. */
    public static void forEach(Path file, Consumer<GameFrame> action) throws IOException {
        forEach(file, action, line -> { });
    }

    /**
     * Hands each frame to {@code action} as it is read, and each {@code server_param},
     * {@code player_param} and {@code player_type} line of a text log to {@code parameters} (those
     * of the JSON form as the same text). An {@link IllegalArgumentException} from either becomes a
     * {@link GameLogException} naming the line.
     */
    public static void forEach(Path file, Consumer<GameFrame> action, Consumer<String> parameters)
            throws IOException {
        GameLogReader reader = new GameLogReader(file, action, parameters);
        try (PushbackInputStream in = new PushbackInputStream(Inputs.open(file), 1)) {
            int first = in.read();
            while (first == ' ' || first == '\t' || first == '\r' || first == '\n') {
                first = in.read();
            }
            if (first < 0) {
                throw new GameLogException(file, 1, "empty game log");
            }
            in.unread(first);
            if (first == '[') {
                reader.readJson(in);
            } else {
                reader.readText(in);
            }
        }
    }

    // ---- text (ULG4 to ULG6)

    private void readText(InputStream in) throws IOException {
        BufferedReader lines = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8), 1 << 16);
        String header = lines.readLine();
        if (header == null || !header.strip().matches("ULG[456]")) {
            throw new GameLogException(file, 1, "not a text game log of version 4 to 6: the first line is '"
                    + shorten(header) + "', not ULG4, ULG5 or ULG6");
        }
        long number = 1;
        String text;
        while ((text = lines.readLine()) != null) {
            number++;
            String line = text.strip();
            if (line.isEmpty()) {
                continue;
            }
            try {
                textLine(line);
            } catch (IllegalArgumentException | IndexOutOfBoundsException | ClassCastException e) {
                throw new GameLogException(file, number, e.getMessage() == null ? "ill-formed line" : e.getMessage(),
                        e instanceof Sexp.OpenList);
            }
        }
    }

    private void textLine(String line) {
        if (line.startsWith("(server_param") || line.startsWith("(player_param") || line.startsWith("(player_type")) {
            parameters.accept(line);
            return;
        }
        if (line.startsWith("(msg") || line.startsWith("(draw") || line.startsWith("(team_graphic")) {
            return;
        }
        List<Object> list = Sexp.parse(line);
        String head = atom(list, 0);
        switch (head) {
            case "playmode" -> {
                intAt(list, 1);
                playMode = atom(list, 2);
            }
            case "team" -> {
                intAt(list, 1);
                leftTeam = teamName(atom(list, 2));
                rightTeam = teamName(atom(list, 3));
                scoreLeft = intAt(list, 4);
                scoreRight = intAt(list, 5);
            }
            case "show" -> frames.accept(show(list));
            default -> throw new IllegalArgumentException("unknown line '" + shorten(line) + "'");
        }
    }

    private GameFrame show(List<Object> list) {
        int time = intAt(list, 1);
        GameFrame.BallState ball = null;
        List<PlayerState> players = new ArrayList<>(22);
        for (int i = 2; i < list.size(); i++) {
            List<Object> item = sub(list, i);
            Object name = item.get(0);
            if (name instanceof String word) {
                // A monitor's show carries the play mode and the score inside.
                if (word.equals("pm")) {
                    int id = intAt(item, 1);
                    if (id < 0 || id >= PLAY_MODES.size()) {
                        throw new IllegalArgumentException("unknown play mode number " + id);
                    }
                    playMode = PLAY_MODES.get(id);
                } else if (word.equals("tm")) {
                    leftTeam = teamName(atom(item, 1));
                    rightTeam = teamName(atom(item, 2));
                    scoreLeft = intAt(item, 3);
                    scoreRight = intAt(item, 4);
                } else {
                    throw new IllegalArgumentException("unexpected (" + word + " ...) in a show");
                }
                continue;
            }
            List<Object> id = sub(item, 0);
            String kind = atom(id, 0);
            if (kind.equals("b")) {
                ball = new GameFrame.BallState(number(item, 1), number(item, 2), number(item, 3), number(item, 4));
            } else {
                PlayerState player = player(item, kind, intAt(id, 1));
                // the server writes all 22 slots; a disabled one (state 0) holds no one in the game
                if (player.state() != 0) {
                    players.add(player);
                }
            }
        }
        if (ball == null) {
            throw new IllegalArgumentException("show " + time + " has no ball");
        }
        return new GameFrame(time, playMode, leftTeam, rightTeam, scoreLeft, scoreRight, ball, players);
    }

    private static PlayerState player(List<Object> item, String side, int unum) {
        if (!side.equals("l") && !side.equals("r")) {
            throw new IllegalArgumentException("a player's side is l or r, not '" + side + "'");
        }
        int numbers = 1;
        while (numbers < item.size() && item.get(numbers) instanceof String) {
            numbers++;
        }
        numbers--; // type, state, x, y, vx, vy, body, neck and, while pointing, the arm's target
        if (numbers != 8 && numbers != 10) {
            throw new IllegalArgumentException("player " + side + " " + unum + " has " + numbers
                    + " numbers after its name, not 8 (or 10 while pointing)");
        }
        int type = intAt(item, 1);
        int state = (int) Long.decode(atom(item, 2)).longValue();
        char quality = 'h';
        double width = 90;
        double stamina = Double.NaN;
        double effort = Double.NaN;
        double recovery = Double.NaN;
        double capacity = Double.NaN;
        PlayerState.Counts counts = null;
        for (int i = numbers + 1; i < item.size(); i++) {
            List<Object> group = sub(item, i);
            switch (atom(group, 0)) {
                case "v" -> {
                    String q = atom(group, 1);
                    if (!q.equals("h") && !q.equals("l")) {
                        throw new IllegalArgumentException("view quality is h or l, not '" + q + "'");
                    }
                    quality = q.charAt(0);
                    width = number(group, 2);
                }
                case "s" -> {
                    stamina = number(group, 1);
                    effort = number(group, 2);
                    recovery = number(group, 3);
                    if (group.size() > 4) {
                        capacity = number(group, 4);
                        capacity = capacity < 0 ? Double.NaN : capacity;
                    }
                }
                case "c" -> {
                    if (group.size() < 12) {
                        throw new IllegalArgumentException("player " + side + " " + unum + " has "
                                + (group.size() - 1) + " command counts, not 11 or 12");
                    }
                    counts = new PlayerState.Counts(intAt(group, 1), intAt(group, 2), intAt(group, 3),
                            intAt(group, 4), intAt(group, 5), intAt(group, 6), intAt(group, 7), intAt(group, 8),
                            intAt(group, 9), intAt(group, 10), intAt(group, 11));
                }
                case "fp", "f", "m" -> {
                }
                default -> throw new IllegalArgumentException("unknown group (" + atom(group, 0) + " ...) of player "
                        + side + " " + unum);
            }
        }
        if (counts == null || Double.isNaN(stamina)) {
            throw new IllegalArgumentException("player " + side + " " + unum + " lacks its (s ...) or (c ...)");
        }
        return new PlayerState(Side.fromLetter(side.charAt(0)), unum, type, state, number(item, 3), number(item, 4),
                number(item, 5), number(item, 6), number(item, 7), number(item, 8), quality, width, stamina, effort,
                recovery, capacity, counts);
    }

    // ---- JSON (game_log_version -1)

    private void readJson(InputStream in) throws IOException {
        JsonParser json = new JsonFactory().createParser(new InputStreamReader(in, StandardCharsets.UTF_8));
        try {
            if (json.nextToken() != JsonToken.START_ARRAY) {
                throw new GameLogException(file, line(json), "a JSON game log is one array");
            }
            JsonToken token;
            while ((token = json.nextToken()) != JsonToken.END_ARRAY) {
                if (token == null) {
                    throw new GameLogException(file, line(json), "the JSON game log ends before its closing ]", true);
                }
                long line = line(json);
                if (token != JsonToken.START_OBJECT) {
                    throw new GameLogException(file, line, "expected an object in the game log's array");
                }
                Map<String, Object> element = object(json);
                try {
                    jsonElement(element);
                } catch (IllegalArgumentException | ClassCastException | NullPointerException e) {
                    throw new GameLogException(file, line, e.getMessage() == null ? "ill-formed element"
                            : e.getMessage());
                }
            }
        } catch (JsonParseException e) {
            throw new GameLogException(file, e.getLocation() == null ? 0 : e.getLocation().getLineNr(),
                    JsonErrors.plain(e.getOriginalMessage()));
        }
    }

    @SuppressWarnings("unchecked")
    private void jsonElement(Map<String, Object> element) {
        for (String head : PARAMETER_HEADS) {
            if (element.get(head) instanceof Map<?, ?> named) {
                parameters.accept(parameterText(head, (Map<String, Object>) named));
                return;
            }
        }
        if (element.containsKey("playmode")) {
            playMode = (String) ((Map<String, Object>) element.get("playmode")).get("mode");
        } else if (element.containsKey("team")) {
            Map<String, Object> team = (Map<String, Object>) element.get("team");
            Map<String, Object> left = (Map<String, Object>) team.get("l");
            Map<String, Object> right = (Map<String, Object>) team.get("r");
            leftTeam = left.get("name") == null ? "" : (String) left.get("name");
            rightTeam = right.get("name") == null ? "" : (String) right.get("name");
            scoreLeft = ((Number) left.get("score")).intValue();
            scoreRight = ((Number) right.get("score")).intValue();
        } else if (element.containsKey("show")) {
            Map<String, Object> show = (Map<String, Object>) element.get("show");
            Map<String, Object> ball = (Map<String, Object>) show.get("ball");
            List<PlayerState> players = new ArrayList<>();
            for (Object each : (List<Object>) show.get("players")) {
                Map<String, Object> p = (Map<String, Object>) each;
                double capacity = p.containsKey("capacity") ? num(p, "capacity") : Double.NaN;
                if ((int) num(p, "state") == 0) {
                    continue; // a disabled slot, as in the text form
                }
                players.add(new PlayerState(Side.fromLetter(((String) p.get("side")).charAt(0)), (int) num(p, "unum"),
                        (int) num(p, "type"), (int) num(p, "state"), num(p, "x"), num(p, "y"), num(p, "vx"),
                        num(p, "vy"), num(p, "body"), num(p, "neck"), ((String) p.get("vq")).charAt(0), num(p, "vw"),
                        num(p, "stamina"), num(p, "effort"), num(p, "recovery"), capacity < 0 ? Double.NaN : capacity,
                        new PlayerState.Counts((int) num(p, "kick"), (int) num(p, "dash"), (int) num(p, "turn"),
                                (int) num(p, "catch"), (int) num(p, "move"), (int) num(p, "turn_neck"),
                                (int) num(p, "change_view"), (int) num(p, "say"), (int) num(p, "tackle"),
                                (int) num(p, "pointto"), (int) num(p, "attentionto"))));
            }
            frames.accept(new GameFrame((int) num(show, "time"), playMode, leftTeam, rightTeam, scoreLeft,
                    scoreRight, new GameFrame.BallState(num(ball, "x"), num(ball, "y"), num(ball, "vx"),
                    num(ball, "vy")), players));
        }
    }

    private static final List<String> PARAMETER_HEADS = List.of("server_param", "player_param", "player_type");

    /**
     * A JSON log's {@code {"server_param":{"name":value,...}}} as the text form's
     * {@code (server_param (name value)...)}: booleans as 1 and 0, as the server's text has them.
     */
    private static String parameterText(String head, Map<String, Object> named) {
        StringBuilder text = new StringBuilder(4096).append('(').append(head);
        for (Map.Entry<String, Object> entry : named.entrySet()) {
            Object value = entry.getValue();
            text.append(" (").append(entry.getKey()).append(' ');
            if (value instanceof Boolean bool) {
                text.append(bool ? '1' : '0');
            } else if (value instanceof Double number) {
                text.append(BigDecimal.valueOf(number).stripTrailingZeros().toPlainString());
            } else if (value instanceof Number number) {
                text.append(number);
            } else if (value != null) {
                text.append('"').append(value.toString().replace('"', '\'')).append('"');
            }
            text.append(')');
        }
        return text.append(')').toString();
    }

    private static double num(Map<String, Object> object, String key) {
        Object value = object.get(key);
        if (!(value instanceof Number number)) {
            throw new IllegalArgumentException("'" + key + "' is missing or not a number");
        }
        return number.doubleValue();
    }

    private static Map<String, Object> object(JsonParser json) throws IOException {
        Map<String, Object> object = new LinkedHashMap<>();
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String key = json.currentName();
            json.nextToken();
            object.put(key, value(json));
        }
        return object;
    }

    private static Object value(JsonParser json) throws IOException {
        switch (json.currentToken()) {
            case START_OBJECT:
                return object(json);
            case START_ARRAY: {
                List<Object> list = new ArrayList<>();
                while (json.nextToken() != JsonToken.END_ARRAY) {
                    list.add(value(json));
                }
                return list;
            }
            case VALUE_STRING:
                return json.getText();
            case VALUE_NUMBER_INT:
            case VALUE_NUMBER_FLOAT:
                return json.getNumberValue();
            case VALUE_TRUE:
                return Boolean.TRUE;
            case VALUE_FALSE:
                return Boolean.FALSE;
            case VALUE_NULL:
                return null;
            default:
                throw new JsonParseException(json, "unexpected " + json.currentToken());
        }
    }

    private static long line(JsonParser json) {
        return json.currentTokenLocation().getLineNr();
    }

    // ---- s-expression helpers

    private static String teamName(String name) {
        return name.equals("null") ? "" : name;
    }

    private static String atom(List<Object> list, int index) {
        if (index >= list.size() || !(list.get(index) instanceof String text)) {
            throw new IllegalArgumentException("expected a word at position " + (index + 1) + " of " + Sexp.show(list));
        }
        return text;
    }

    @SuppressWarnings("unchecked")
    private static List<Object> sub(List<Object> list, int index) {
        if (index >= list.size() || !(list.get(index) instanceof List<?>)) {
            throw new IllegalArgumentException("expected a list at position " + (index + 1) + " of " + Sexp.show(list));
        }
        return (List<Object>) list.get(index);
    }

    private static int intAt(List<Object> list, int index) {
        String text = atom(list, index);
        try {
            return Integer.parseInt(text);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "' is not a whole number in " + Sexp.show(list));
        }
    }

    private static double number(List<Object> list, int index) {
        String text = atom(list, index);
        double plain = plainDecimal(text);
        if (!Double.isNaN(plain)) {
            return plain;
        }
        try {
            return Double.parseDouble(text);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "' is not a number in " + Sexp.show(list));
        }
    }

    /**
     * A number written as digits with at most one point and a sign, as the server writes them,
     * parsed without {@link Double#parseDouble} (a game log holds millions): exact, as that method,
     * for up to 15 digits (one correctly rounded division of two exact doubles); NaN for any other
     * text, which that method then reads.
     */
    static double plainDecimal(String text) {
        int i = text.isEmpty() || (text.charAt(0) != '-' && text.charAt(0) != '+') ? 0 : 1;
        long mantissa = 0;
        int digits = 0;
        int fraction = -1;
        for (; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c >= '0' && c <= '9' && digits < 15) {
                mantissa = mantissa * 10 + (c - '0');
                digits++;
                fraction += fraction >= 0 ? 1 : 0;
            } else if (c == '.' && fraction < 0) {
                fraction = 0;
            } else {
                return Double.NaN;
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        double value = fraction <= 0 ? mantissa : mantissa / POWERS_OF_TEN[fraction];
        return text.charAt(0) == '-' ? -value : value;
    }

    private static String shorten(String text) {
        if (text == null) {
            return "";
        }
        return text.length() <= 60 ? text : text.substring(0, 60) + "...";
    }

    /** Balanced lists of words and quoted strings, as game log lines are written. */
    private static final class Sexp {
        /** The line's characters: read from an array, not through {@code String.charAt} (millions a game). */
        private final char[] text;
        private int pos;

        private Sexp(String text) {
            this.text = text.toCharArray();
        }

        /** A line that ends before a list closes: the log was cut there (typed, so no one matches the text). */
        static final class OpenList extends IllegalArgumentException {
            OpenList() {
                super("unbalanced parentheses: the line ends inside a list");
            }
        }

        static List<Object> parse(String text) {
            Sexp sexp = new Sexp(text);
            sexp.skipSpace();
            if (sexp.pos >= text.length() || text.charAt(sexp.pos) != '(') {
                throw new IllegalArgumentException("expected '(' at column 1");
            }
            List<Object> list = sexp.list();
            sexp.skipSpace();
            if (sexp.pos != text.length()) {
                throw new IllegalArgumentException("text after the closing ')' at column " + (sexp.pos + 1));
            }
            return list;
        }

        private List<Object> list() {
            pos++; // '('
            // a player's list has 13 to 17 items
            List<Object> items = new ArrayList<>(16);
            while (true) {
                skipSpace();
                if (pos >= text.length) {
                    throw new OpenList();
                }
                char c = text[pos];
                if (c == ')') {
                    pos++;
                    return items;
                } else if (c == '(') {
                    items.add(list());
                } else if (c == '"') {
                    int close = pos + 1;
                    while (close < text.length && text[close] != '"') {
                        close++;
                    }
                    if (close >= text.length) {
                        throw new IllegalArgumentException("unterminated string at column " + (pos + 1));
                    }
                    items.add(new String(text, pos, close + 1 - pos));
                    pos = close + 1;
                } else {
                    int start = pos;
                    while (pos < text.length && !isSpace(text[pos]) && text[pos] != '(' && text[pos] != ')') {
                        pos++;
                    }
                    items.add(new String(text, start, pos - start));
                }
            }
        }

        private void skipSpace() {
            while (pos < text.length && isSpace(text[pos])) {
                pos++;
            }
        }

        /** {@link Character#isWhitespace}, without its look-up for the printable ASCII between. */
        private static boolean isSpace(char c) {
            return c == ' ' || ((c < ' ' || c > '~') && Character.isWhitespace(c));
        }

        static String show(List<Object> list) {
            StringBuilder out = new StringBuilder("(");
            for (int i = 0; i < list.size(); i++) {
                if (i > 0) {
                    out.append(' ');
                }
                Object item = list.get(i);
                out.append(item instanceof List<?> ? "(...)" : item);
            }
            String text = out.append(')').toString();
            return text.length() <= 80 ? text : text.substring(0, 80) + "...";
        }
    }
}
