package org.scenes.internal.scene;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.io.JsonEOFException;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;
import java.util.function.Function;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.files.IoErrors;
import org.scenes.internal.files.JsonErrors;

/**
 * Streams the scenes of a scene file one at a time, never holding the JSON tree, so files
 * of millions of scenes load in the memory their scenes need. The header ({@code format},
 * {@code grid}, {@code source}) must precede {@code scenes}, with {@code format} first.
 * Any problem is a {@link SceneFileException} naming file, line and column.
 */
public final class SceneFileReader implements Iterator<Scene>, AutoCloseable {
    private final Path file;
    private final JsonParser json;
    private final SceneFileHeader header;
    private Scene next;
    private boolean finished;

    private SceneFileReader(Path file, InputStream in) throws IOException {
        this.file = file;
        this.json = SceneFileWriter.JSON.createParser(in);
        this.header = readHeader();
    }

    /** Opens a scene file (gzip or plain) and reads its header. */
    public static SceneFileReader open(Path file) {
        InputStream in;
        try {
            in = Inputs.open(file);
        } catch (NoSuchFileException e) {
            throw new SceneFileException(file, 0, 0, "no such file", e);
        } catch (IOException e) {
            throw new SceneFileException(file, 0, 0, "cannot open: " + IoErrors.reason(e), e);
        }
        try {
            return new SceneFileReader(file, in);
        } catch (IOException | RuntimeException e) {
            closeQuietly(in);
            throw asSceneFileException(file, null, e);
        }
    }

    /** Reads a whole file; on any error nothing is returned. */
    public static SceneFile read(Path file) {
        try (SceneFileReader reader = open(file)) {
            List<Scene> scenes = new ArrayList<>();
            reader.forEachRemaining(scenes::add);
            return new SceneFile(reader.header(), scenes);
        }
    }

    public SceneFileHeader header() {
        return header;
    }

    @Override
    public boolean hasNext() {
        if (next == null && !finished) {
            try {
                next = readScene();
            } catch (IOException | RuntimeException e) {
                throw asSceneFileException(file, json, e);
            }
        }
        return next != null;
    }

    @Override
    public Scene next() {
        if (!hasNext()) {
            throw new NoSuchElementException();
        }
        Scene scene = next;
        next = null;
        return scene;
    }

    @Override
    public void close() {
        try {
            json.close();
        } catch (IOException e) {
            // nothing was written; a failing close of an input cannot lose data
        }
    }

    private SceneFileHeader readHeader() throws IOException {
        expect(json.nextToken(), JsonToken.START_OBJECT, "a JSON object with 'format' first");
        if (json.nextToken() != JsonToken.FIELD_NAME || !"format".equals(json.currentName())) {
            throw error("expected the field 'format' first (is this a scene file?)");
        }
        expect(json.nextToken(), JsonToken.VALUE_NUMBER_INT, "an integer format version");
        int format = json.getIntValue();
        if (format > SceneFileHeader.CURRENT_FORMAT) {
            throw error("scene format " + format + " is newer than this version of scenes reads (up to "
                    + SceneFileHeader.CURRENT_FORMAT + "); upgrade scenes to read it");
        }
        if (format < 1) {
            throw error("scene format must be at least 1, not " + format);
        }
        Grid grid = null;
        SceneSource source = new SceneSource("", Observer.UNKNOWN);
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String field = json.currentName();
            JsonToken value = json.nextToken();
            switch (field) {
                case "grid" -> grid = readGrid(value);
                case "source" -> source = readSource(value);
                case "scenes" -> {
                    if (grid == null) {
                        throw error("'grid' must come before 'scenes'");
                    }
                    expect(value, JsonToken.START_ARRAY, "an array of scenes");
                    return new SceneFileHeader(format, grid, source);
                }
                default -> json.skipChildren();
            }
        }
        throw error("expected the field 'scenes'");
    }

    private Grid readGrid(JsonToken start) throws IOException {
        expect(start, JsonToken.START_OBJECT, "a grid object");
        int columns = -1;
        int rows = -1;
        double minAngle = Grid.DEFAULT.minAngle();
        double maxAngle = Grid.DEFAULT.maxAngle();
        double[] bounds = null;
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String field = json.currentName();
            JsonToken value = json.nextToken();
            switch (field) {
                case "columns" -> columns = intValue(value);
                case "rows" -> rows = intValue(value);
                case "minAngle" -> minAngle = number(value);
                case "maxAngle" -> maxAngle = number(value);
                case "bounds" -> {
                    expect(value, JsonToken.START_ARRAY, "an array of distance bounds");
                    List<Double> list = new ArrayList<>();
                    while (json.nextToken() != JsonToken.END_ARRAY) {
                        list.add(number(json.currentToken()));
                    }
                    bounds = list.stream().mapToDouble(Double::doubleValue).toArray();
                }
                default -> json.skipChildren();
            }
        }
        if (columns < 0 || bounds == null) {
            throw error("the grid needs 'columns' and 'bounds'");
        }
        if (rows >= 0 && rows != bounds.length + 1) {
            throw error("the grid has " + rows + " rows but " + bounds.length + " bounds (rows = bounds + 1)");
        }
        try {
            return new Grid(columns, minAngle, maxAngle, bounds);
        } catch (IllegalArgumentException e) {
            throw error(e.getMessage());
        }
    }

    private SceneSource readSource(JsonToken start) throws IOException {
        expect(start, JsonToken.START_OBJECT, "a source object");
        String log = "";
        Observer observer = Observer.UNKNOWN;
        boolean goalie = false;
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String field = json.currentName();
            JsonToken value = json.nextToken();
            if ("log".equals(field)) {
                log = text(value);
            } else if ("goalie".equals(field)) {
                goalie = bool(value);
            } else {
                observer = readObserverField(observer, field, value);
            }
        }
        return new SceneSource(log, observer, goalie);
    }

    private Observer readObserverField(Observer observer, String field, JsonToken value) throws IOException {
        switch (field) {
            case "team":
                return new Observer(text(value), observer.side(), observer.uniformNumber());
            case "side":
                String side = text(value);
                if (side.length() != 1 || (side.charAt(0) != 'l' && side.charAt(0) != 'r')) {
                    throw error("side must be \"l\" or \"r\", not \"" + side + "\"");
                }
                return new Observer(observer.team(), Side.fromLetter(side.charAt(0)), observer.uniformNumber());
            case "unum":
                return new Observer(observer.team(), observer.side(), intValue(value));
            default:
                json.skipChildren();
                return observer;
        }
    }

    private Scene readScene() throws IOException {
        JsonToken token = json.nextToken();
        if (token == JsonToken.END_ARRAY) {
            finishDocument();
            return null;
        }
        expect(token, JsonToken.START_OBJECT, "a scene object or the end of 'scenes'");
        JsonLocation start = json.currentTokenLocation();
        int cycle = Integer.MIN_VALUE;
        int seeAge = 0;
        Observer observer = header.source().observer();
        List<SeenObject> objects = null;
        List<Action> actions = null;
        World world = null;
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String field = json.currentName();
            JsonToken value = json.nextToken();
            switch (field) {
                case "cycle" -> cycle = intValue(value);
                case "seeAge" -> seeAge = intValue(value);
                case "observer" -> {
                    expect(value, JsonToken.START_OBJECT, "an observer object");
                    while (json.nextToken() == JsonToken.FIELD_NAME) {
                        String observerField = json.currentName();
                        observer = readObserverField(observer, observerField, json.nextToken());
                    }
                }
                case "objects" -> objects = readObjects(value);
                case "actions" -> actions = readActions(value);
                case "world" -> world = readWorld(value);
                default -> json.skipChildren();
            }
        }
        if (cycle == Integer.MIN_VALUE || objects == null || actions == null) {
            throw new SceneFileException(file, start.getLineNr(), start.getColumnNr(),
                    "a scene needs 'cycle', 'objects' and 'actions'", null);
        }
        try {
            return new Scene(cycle, observer, objects, actions, null, seeAge, world);
        } catch (IllegalArgumentException e) {
            throw new SceneFileException(file, start.getLineNr(), start.getColumnNr(), e.getMessage(), e);
        }
    }

    private void finishDocument() throws IOException {
        finished = true;
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            json.nextToken();
            json.skipChildren();
        }
        expect(json.currentToken(), JsonToken.END_OBJECT, "the end of the scene file");
        if (json.nextToken() != null) {
            throw error("unexpected content after the end of the scene file");
        }
    }

    private List<SeenObject> readObjects(JsonToken start) throws IOException {
        expect(start, JsonToken.START_ARRAY, "an array of objects");
        List<SeenObject> objects = new ArrayList<>();
        while (json.nextToken() != JsonToken.END_ARRAY) {
            if (objects.size() == SceneValues.MAX_OBJECTS) {
                throw error("a scene holds at most " + SceneValues.MAX_OBJECTS + " objects (a see of the soccer server"
                        + " lists fewer than 100); is this a scene file?");
            }
            objects.add(readObject(json.currentToken()));
        }
        return objects;
    }

    private SeenObject readObject(JsonToken start) throws IOException {
        expect(start, JsonToken.START_OBJECT, "an object");
        ObjectKind kind = null;
        String name = null;
        String team = "";
        int unum = 0;
        boolean goalie = false;
        Relation relation = Relation.NONE;
        double distance = Double.NaN;
        double direction = Double.NaN;
        double distanceChange = Double.NaN;
        double directionChange = Double.NaN;
        double bodyFacing = Double.NaN;
        double headFacing = Double.NaN;
        double pointing = Double.NaN;
        char mark = SeenObject.NO_MARK;
        Cell cell = null;
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String field = json.currentName();
            JsonToken value = json.nextToken();
            switch (field) {
                case "kind" -> kind = parseEnum(value, ObjectKind::fromKey);
                case "name" -> name = text(value);
                case "team" -> team = text(value);
                case "unum" -> unum = intValue(value);
                case "goalie" -> goalie = bool(value);
                case "relation" -> relation = parseEnum(value, Relation::fromKey);
                case "dist" -> distance = inRange(field, number(value), 0, SceneValues.MAX_DISTANCE);
                case "dir" -> direction = inRange(field, number(value), -SceneValues.MAX_DIRECTION, SceneValues.MAX_DIRECTION);
                case "distChange" -> distanceChange = inRange(field, number(value), -SceneValues.MAX_CHANGE, SceneValues.MAX_CHANGE);
                case "dirChange" -> directionChange = inRange(field, number(value), -SceneValues.MAX_CHANGE, SceneValues.MAX_CHANGE);
                case "bodyFacing" -> bodyFacing = inRange(field, number(value), -SceneValues.MAX_DIRECTION, SceneValues.MAX_DIRECTION);
                case "headFacing" -> headFacing = inRange(field, number(value), -SceneValues.MAX_DIRECTION, SceneValues.MAX_DIRECTION);
                case "pointDir" -> pointing = inRange(field, number(value), -SceneValues.MAX_DIRECTION, SceneValues.MAX_DIRECTION);
                case "mark" -> {
                    String text = text(value);
                    if (!text.equals("t") && !text.equals("k")) {
                        throw error("mark must be \"t\" or \"k\", not \"" + text + "\"");
                    }
                    mark = text.charAt(0);
                }
                case "cell" -> cell = readCell(value);
                default -> json.skipChildren();
            }
        }
        if (kind == null || name == null || name.isEmpty() || cell == null) {
            throw error("an object needs 'kind', 'name' and 'cell'");
        }
        return new SeenObject(kind, name, team, unum, goalie, relation, distance, direction,
                distanceChange, directionChange, bodyFacing, headFacing, pointing, mark, cell);
    }

    /** A scene's world model (format 2); values left out are unknown (NaN, age -1). */
    private World readWorld(JsonToken start) throws IOException {
        expect(start, JsonToken.START_OBJECT, "a world object");
        double[] self = {Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN};
        double[] ball = {Double.NaN, Double.NaN, Double.NaN, Double.NaN};
        int age = -1;
        int ballAge = -1;
        List<World.Player> players = new ArrayList<>();
        String playMode = "";
        int own = 0;
        int opponent = 0;
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String field = json.currentName();
            JsonToken value = json.nextToken();
            int index = WORLD_NUMBERS.indexOf(field);
            if (index >= 0) {
                self[index] = number(value);
                continue;
            }
            switch (field) {
                case "age" -> age = intValue(value);
                case "ball" -> {
                    expect(value, JsonToken.START_OBJECT, "a ball object");
                    while (json.nextToken() == JsonToken.FIELD_NAME) {
                        String ballField = json.currentName();
                        JsonToken ballValue = json.nextToken();
                        switch (ballField) {
                            case "x" -> ball[0] = number(ballValue);
                            case "y" -> ball[1] = number(ballValue);
                            case "vx" -> ball[2] = number(ballValue);
                            case "vy" -> ball[3] = number(ballValue);
                            case "age" -> ballAge = intValue(ballValue);
                            default -> json.skipChildren();
                        }
                    }
                }
                case "players" -> {
                    expect(value, JsonToken.START_ARRAY, "an array of players");
                    while (json.nextToken() != JsonToken.END_ARRAY) {
                        players.add(readWorldPlayer(json.currentToken()));
                    }
                }
                case "playMode" -> playMode = text(value);
                case "score" -> {
                    expect(value, JsonToken.START_ARRAY, "a score [own, opponent]");
                    own = intValue(json.nextToken());
                    opponent = intValue(json.nextToken());
                    expect(json.nextToken(), JsonToken.END_ARRAY, "the end of the score [own, opponent]");
                }
                default -> json.skipChildren();
            }
        }
        return new World(self[0], self[1], self[2], self[3], self[4], self[5], self[6], self[7], age,
                ball[0], ball[1], ball[2], ball[3], ballAge, players, playMode, own, opponent);
    }

    /** The world block's own numbers, in {@link World}'s order. */
    private static final List<String> WORLD_NUMBERS = List.of("x", "y", "body", "neck", "vx", "vy", "stamina", "effort");

    private World.Player readWorldPlayer(JsonToken start) throws IOException {
        expect(start, JsonToken.START_OBJECT, "a player object");
        Relation relation = Relation.UNKNOWN;
        int unum = 0;
        double x = Double.NaN;
        double y = Double.NaN;
        int age = 0;
        while (json.nextToken() == JsonToken.FIELD_NAME) {
            String field = json.currentName();
            JsonToken value = json.nextToken();
            switch (field) {
                case "relation" -> relation = parseEnum(value, Relation::fromKey);
                case "unum" -> unum = intValue(value);
                case "x" -> x = number(value);
                case "y" -> y = number(value);
                case "age" -> age = intValue(value);
                default -> json.skipChildren();
            }
        }
        return new World.Player(relation, unum, x, y, age);
    }

    private Cell readCell(JsonToken start) throws IOException {
        expect(start, JsonToken.START_ARRAY, "a cell [column, row]");
        int column = intValue(json.nextToken());
        int row = intValue(json.nextToken());
        expect(json.nextToken(), JsonToken.END_ARRAY, "the end of the cell [column, row]");
        Grid grid = header.grid();
        if (column < 0 || column >= grid.columns() || row < 0 || row >= grid.rows()) {
            throw error("cell [" + column + ", " + row + "] lies outside the file's " + grid.describe() + " grid");
        }
        return new Cell(column, row);
    }

    private List<Action> readActions(JsonToken start) throws IOException {
        expect(start, JsonToken.START_ARRAY, "an array of actions");
        List<Action> actions = new ArrayList<>(2);
        while (json.nextToken() != JsonToken.END_ARRAY) {
            expect(json.currentToken(), JsonToken.START_OBJECT, "an action object");
            ActionType type = null;
            double[] parameters = {Double.NaN, Double.NaN};
            List<String> fields = new ArrayList<>();
            List<Double> values = new ArrayList<>();
            List<String> notNumbers = new ArrayList<>();
            while (json.nextToken() == JsonToken.FIELD_NAME) {
                String field = json.currentName();
                JsonToken value = json.nextToken();
                if ("type".equals(field)) {
                    type = parseEnum(value, ActionType::fromKey);
                } else if ("primary".equals(field)) {
                    bool(value);
                } else if (value.isNumeric()) {
                    fields.add(field);
                    values.add(inRange(field, json.getDoubleValue(), -SceneValues.MAX_PARAMETER, SceneValues.MAX_PARAMETER));
                } else {
                    notNumbers.add(field + "' is " + describe(value));
                    json.skipChildren();
                }
            }
            if (type == null) {
                throw error("an action needs a 'type'");
            }
            for (String notNumber : notNumbers) {
                String field = notNumber.substring(0, notNumber.indexOf('\''));
                for (int i = 0; i < type.parameterCount(); i++) {
                    if (type.parameter(i).equals(field)) {
                        // a parameter of another type would be dropped silently: a wrong file, not a missing value
                        throw error("action '" + type.key() + "': '" + notNumber + ", not a number");
                    }
                }
            }
            for (int i = 0; i < fields.size(); i++) {
                int index = parameterIndex(type, fields.get(i));
                parameters[index] = values.get(i);
            }
            actions.add(new Action(type, parameters[0], parameters[1]));
        }
        return actions;
    }

    private int parameterIndex(ActionType type, String field) {
        for (int i = 0; i < type.parameterCount(); i++) {
            if (type.parameter(i).equals(field)) {
                return i;
            }
        }
        throw error("action '" + type.key() + "' has no parameter '" + field + "'");
    }

    private <T> T parseEnum(JsonToken value, Function<String, T> parse) throws IOException {
        String text = text(value);
        try {
            return parse.apply(text);
        } catch (IllegalArgumentException e) {
            throw error(e.getMessage());
        }
    }

    private void expect(JsonToken actual, JsonToken expected, String what) {
        if (actual != expected) {
            throw error("expected " + what + " but found " + describe(actual));
        }
    }

    private String text(JsonToken value) throws IOException {
        expect(value, JsonToken.VALUE_STRING, "a string");
        return json.getText();
    }

    private int intValue(JsonToken value) throws IOException {
        expect(value, JsonToken.VALUE_NUMBER_INT, "an integer");
        return json.getIntValue();
    }

    private double number(JsonToken value) throws IOException {
        if (value != JsonToken.VALUE_NUMBER_INT && value != JsonToken.VALUE_NUMBER_FLOAT) {
            throw error("expected a number but found " + describe(value));
        }
        return json.getDoubleValue();
    }

    /** A scene's number: finite and within what the soccer server can send. */
    private double inRange(String field, double value, double lowest, double highest) {
        if (!(value >= lowest && value <= highest)) {
            throw error("'" + field + "' must be a finite number from " + SceneValues.format(lowest) + " to "
                    + SceneValues.format(highest) + ", not " + value);
        }
        return value;
    }

    private boolean bool(JsonToken value) {
        if (value != JsonToken.VALUE_TRUE && value != JsonToken.VALUE_FALSE) {
            throw error("expected true or false but found " + describe(value));
        }
        return value == JsonToken.VALUE_TRUE;
    }

    private static String describe(JsonToken token) {
        if (token == null) {
            return "the end of the file (is it truncated?)";
        }
        return switch (token) {
            case START_OBJECT -> "an object";
            case END_OBJECT -> "the end of an object";
            case START_ARRAY -> "an array";
            case END_ARRAY -> "the end of an array";
            case FIELD_NAME -> "a field name";
            case VALUE_STRING -> "a string";
            case VALUE_NUMBER_INT, VALUE_NUMBER_FLOAT -> "a number";
            case VALUE_TRUE, VALUE_FALSE -> "a boolean";
            case VALUE_NULL -> "null";
            default -> token.toString();
        };
    }

    private SceneFileException error(String message) {
        JsonLocation location = json.currentTokenLocation();
        return new SceneFileException(file, location.getLineNr(), location.getColumnNr(), message, null);
    }

    private static SceneFileException asSceneFileException(Path file, JsonParser json, Exception e) {
        if (e instanceof SceneFileException sceneError) {
            return sceneError;
        }
        if (e instanceof JsonEOFException eof) {
            JsonLocation location = eof.getLocation();
            return new SceneFileException(file, location.getLineNr(), location.getColumnNr(),
                    "the file ends in the middle of the JSON (is it truncated?)", e);
        }
        if (e instanceof JsonProcessingException jsonError) {
            JsonLocation location = jsonError.getLocation();
            return new SceneFileException(file, location == null ? 0 : location.getLineNr(),
                    location == null ? 0 : location.getColumnNr(),
                    "malformed JSON: " + JsonErrors.plain(jsonError.getOriginalMessage()), e);
        }
        if (e instanceof EOFException) {
            return new SceneFileException(file, 0, 0, "the compressed file ends early (is it truncated?)", e);
        }
        if (e instanceof Inputs.CorruptCompressionException corrupt) {
            return new SceneFileException(file, 0, 0, corrupt.reason(), e);
        }
        long line = json == null ? 0 : json.currentLocation().getLineNr();
        long column = json == null ? 0 : json.currentLocation().getColumnNr();
        return new SceneFileException(file, line, column, e.getMessage(), e);
    }

    private static void closeQuietly(InputStream in) {
        try {
            in.close();
        } catch (IOException ignored) {
            // reporting the original failure matters more
        }
    }
}
