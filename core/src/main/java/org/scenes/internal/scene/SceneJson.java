package org.scenes.internal.scene;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Function;

/**
 * The JSON of one scene file being read, with the checked reads every part of the file shares:
 * each wrong token is a {@link SceneFileException} naming the file, line and column.
 */
final class SceneJson {
    final Path file;
    final JsonParser json;

    SceneJson(Path file, JsonParser json) {
        this.file = file;
        this.json = json;
    }

    JsonToken next() throws IOException {
        return json.nextToken();
    }

    String fieldName() throws IOException {
        return json.currentName();
    }

    void skipChildren() throws IOException {
        json.skipChildren();
    }

    void expect(JsonToken actual, JsonToken expected, String what) {
        if (actual != expected) {
            throw error("expected " + what + " but found " + describe(actual));
        }
    }

    String text(JsonToken value) throws IOException {
        expect(value, JsonToken.VALUE_STRING, "a string");
        return json.getText();
    }

    int intValue(JsonToken value) throws IOException {
        expect(value, JsonToken.VALUE_NUMBER_INT, "an integer");
        return json.getIntValue();
    }

    double number(JsonToken value) throws IOException {
        if (value != JsonToken.VALUE_NUMBER_INT && value != JsonToken.VALUE_NUMBER_FLOAT) {
            throw error("expected a number but found " + describe(value));
        }
        return json.getDoubleValue();
    }

    /** A scene's number: finite and within what the soccer server can send. */
    double inRange(String field, double value, double lowest, double highest) {
        if (!(value >= lowest && value <= highest)) {
            throw error("'" + field + "' must be a finite number from " + SceneValues.format(lowest) + " to "
                    + SceneValues.format(highest) + ", not " + value);
        }
        return value;
    }

    boolean bool(JsonToken value) {
        if (value != JsonToken.VALUE_TRUE && value != JsonToken.VALUE_FALSE) {
            throw error("expected true or false but found " + describe(value));
        }
        return value == JsonToken.VALUE_TRUE;
    }

    <T> T parseEnum(JsonToken value, Function<String, T> parse) throws IOException {
        String text = text(value);
        try {
            return parse.apply(text);
        } catch (IllegalArgumentException e) {
            throw error(e.getMessage());
        }
    }

    static String describe(JsonToken token) {
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

    /** An error at the current token. */
    SceneFileException error(String message) {
        return errorAt(json.currentTokenLocation(), message);
    }

    SceneFileException errorAt(JsonLocation location, String message) {
        return new SceneFileException(file, location.getLineNr(), location.getColumnNr(), message, null);
    }
}
