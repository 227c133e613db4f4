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
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
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
    private final SceneJson in;
    private final SceneFileHeader header;
    private final ObjectsReader objectsReader;
    private final WorldReader worldReader;
    private Scene next;
    private boolean finished;

    private SceneFileReader(Path file, InputStream stream) throws IOException {
        this.in = new SceneJson(file, SceneFileWriter.JSON.createParser(stream));
        this.header = readHeader();
        this.objectsReader = new ObjectsReader(in, header.grid(), header.format());
        this.worldReader = new WorldReader(in, header.format());
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
                throw asSceneFileException(in.file, in.json, e);
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
            in.json.close();
        } catch (IOException e) {
            // nothing was written; a failing close of an input cannot lose data
        }
    }

    private SceneFileHeader readHeader() throws IOException {
        in.expect(in.next(), JsonToken.START_OBJECT, "a JSON object with 'format' first");
        if (in.next() != JsonToken.FIELD_NAME || !"format".equals(in.fieldName())) {
            throw in.error("expected the field 'format' first (is this a scene file?)");
        }
        in.expect(in.next(), JsonToken.VALUE_NUMBER_INT, "an integer format version");
        int format = in.json.getIntValue();
        if (format > SceneFileHeader.CURRENT_FORMAT) {
            throw in.error("scene format " + format + " is newer than this version of scenes reads (up to "
                    + SceneFileHeader.CURRENT_FORMAT + "); upgrade scenes to read it");
        }
        if (format < 1) {
            throw in.error("scene format must be at least 1, not " + format);
        }
        Grid grid = null;
        SceneSource source = new SceneSource("", Observer.UNKNOWN);
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            switch (field) {
                case "grid" -> grid = readGrid(value);
                case "source" -> source = readSource(value);
                case "scenes" -> {
                    if (grid == null) {
                        throw in.error("'grid' must come before 'scenes'");
                    }
                    in.expect(value, JsonToken.START_ARRAY, "an array of scenes");
                    return new SceneFileHeader(format, grid, source);
                }
                default -> in.skipChildren();
            }
        }
        throw in.error("expected the field 'scenes'");
    }

    private Grid readGrid(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_OBJECT, "a grid object");
        int columns = -1;
        int rows = -1;
        double minAngle = Grid.DEFAULT.minAngle();
        double maxAngle = Grid.DEFAULT.maxAngle();
        double[] bounds = null;
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            switch (field) {
                case "columns" -> columns = in.intValue(value);
                case "rows" -> rows = in.intValue(value);
                case "minAngle" -> minAngle = in.number(value);
                case "maxAngle" -> maxAngle = in.number(value);
                case "bounds" -> {
                    in.expect(value, JsonToken.START_ARRAY, "an array of distance bounds");
                    List<Double> list = new ArrayList<>();
                    while (in.next() != JsonToken.END_ARRAY) {
                        list.add(in.number(in.json.currentToken()));
                    }
                    bounds = list.stream().mapToDouble(Double::doubleValue).toArray();
                }
                default -> in.skipChildren();
            }
        }
        if (columns < 0 || bounds == null) {
            throw in.error("the grid needs 'columns' and 'bounds'");
        }
        if (rows >= 0 && rows != bounds.length + 1) {
            throw in.error("the grid has " + rows + " rows but " + bounds.length + " bounds (rows = bounds + 1)");
        }
        try {
            return new Grid(columns, minAngle, maxAngle, bounds);
        } catch (IllegalArgumentException e) {
            throw in.error(e.getMessage());
        }
    }

    private SceneSource readSource(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_OBJECT, "a source object");
        String log = "";
        Observer observer = Observer.UNKNOWN;
        boolean goalie = false;
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            if ("log".equals(field)) {
                log = in.text(value);
            } else if ("goalie".equals(field)) {
                goalie = in.bool(value);
            } else {
                observer = readObserverField(observer, field, value);
            }
        }
        return new SceneSource(log, observer, goalie);
    }

    private Observer readObserverField(Observer observer, String field, JsonToken value) throws IOException {
        switch (field) {
            case "team":
                return new Observer(in.text(value), observer.side(), observer.uniformNumber());
            case "side":
                String side = in.text(value);
                if (side.length() != 1 || (side.charAt(0) != 'l' && side.charAt(0) != 'r')) {
                    throw in.error("side must be \"l\" or \"r\", not \"" + side + "\"");
                }
                return new Observer(observer.team(), Side.fromLetter(side.charAt(0)), observer.uniformNumber());
            case "unum":
                return new Observer(observer.team(), observer.side(), in.intValue(value));
            default:
                in.skipChildren();
                return observer;
        }
    }

    private Scene readScene() throws IOException {
        JsonToken token = in.next();
        if (token == JsonToken.END_ARRAY) {
            finishDocument();
            return null;
        }
        in.expect(token, JsonToken.START_OBJECT, "a scene object or the end of 'scenes'");
        JsonLocation start = in.json.currentTokenLocation();
        int cycle = Integer.MIN_VALUE;
        int seeAge = 0;
        Observer observer = header.source().observer();
        List<SeenObject> objects = null;
        List<Action> actions = null;
        World world = null;
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            switch (field) {
                case "cycle" -> cycle = in.intValue(value);
                case "seeAge" -> seeAge = in.intValue(value);
                case "observer" -> {
                    if (objects != null && header.format() >= 3) {
                        // format 3 derives the objects' relations from the observer
                        throw in.error("'observer' must come before 'objects'");
                    }
                    in.expect(value, JsonToken.START_OBJECT, "an observer object");
                    while (in.next() == JsonToken.FIELD_NAME) {
                        String observerField = in.fieldName();
                        observer = readObserverField(observer, observerField, in.next());
                    }
                }
                case "objects" -> objects = objectsReader.read(value, observer);
                case "actions" -> actions = readActions(value);
                case "world" -> world = worldReader.read(value);
                default -> in.skipChildren();
            }
        }
        if (cycle == Integer.MIN_VALUE || objects == null || actions == null) {
            throw in.errorAt(start, "a scene needs 'cycle', 'objects' and 'actions'");
        }
        try {
            return new Scene(cycle, observer, objects, actions, null, seeAge, world);
        } catch (IllegalArgumentException e) {
            throw new SceneFileException(in.file, start.getLineNr(), start.getColumnNr(), e.getMessage(), e);
        }
    }

    private void finishDocument() throws IOException {
        finished = true;
        while (in.next() == JsonToken.FIELD_NAME) {
            in.next();
            in.skipChildren();
        }
        in.expect(in.json.currentToken(), JsonToken.END_OBJECT, "the end of the scene file");
        if (in.next() != null) {
            throw in.error("unexpected content after the end of the scene file");
        }
    }

    private List<Action> readActions(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_ARRAY, "an array of actions");
        List<Action> actions = new ArrayList<>(2);
        while (in.next() != JsonToken.END_ARRAY) {
            in.expect(in.json.currentToken(), JsonToken.START_OBJECT, "an action object");
            ActionType type = null;
            double[] parameters = {Double.NaN, Double.NaN};
            List<String> fields = new ArrayList<>();
            List<Double> values = new ArrayList<>();
            List<String> notNumbers = new ArrayList<>();
            while (in.next() == JsonToken.FIELD_NAME) {
                String field = in.fieldName();
                JsonToken value = in.next();
                if ("type".equals(field)) {
                    type = in.parseEnum(value, ActionType::fromKey);
                } else if ("primary".equals(field)) {
                    in.bool(value);
                } else if (value.isNumeric()) {
                    fields.add(field);
                    values.add(in.inRange(field, in.json.getDoubleValue(), -SceneValues.MAX_PARAMETER, SceneValues.MAX_PARAMETER));
                } else {
                    notNumbers.add(field + "' is " + SceneJson.describe(value));
                    in.skipChildren();
                }
            }
            if (type == null) {
                throw in.error("an action needs a 'type'");
            }
            for (String notNumber : notNumbers) {
                String field = notNumber.substring(0, notNumber.indexOf('\''));
                for (int i = 0; i < type.parameterCount(); i++) {
                    if (type.parameter(i).equals(field)) {
                        // a parameter of another type would be dropped silently: a wrong file, not a missing value
                        throw in.error("action '" + type.key() + "': '" + notNumber + ", not a number");
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
        throw in.error("action '" + type.key() + "' has no parameter '" + field + "'");
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
