package org.scenes.internal.scene;

import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.SeenObject;

/**
 * Reads a scene's {@code objects}: arrays in format 3 ({@link CompactObject}), objects with named
 * fields, {@code kind} and {@code cell} in formats 1 and 2.
 */
final class ObjectsReader {
    private final SceneJson in;
    private final Grid grid;
    private final boolean compact;
    private final double[] numbers = new double[CompactObject.NUMBERS.length];
    private final Identity identity = new Identity();

    ObjectsReader(SceneJson in, Grid grid, int format) {
        this.in = in;
        this.grid = grid;
        this.compact = format >= 3;
    }

    /** The objects of a scene seen by {@code observer} (which format 3 derives relations from). */
    List<SeenObject> read(JsonToken start, Observer observer) throws IOException {
        in.expect(start, JsonToken.START_ARRAY, "an array of objects");
        List<SeenObject> objects = new ArrayList<>();
        while (in.next() != JsonToken.END_ARRAY) {
            if (objects.size() == SceneValues.MAX_OBJECTS) {
                throw in.error("a scene holds at most " + SceneValues.MAX_OBJECTS + " objects (a see of the soccer server"
                        + " lists fewer than 100); is this a scene file?");
            }
            JsonToken token = in.json.currentToken();
            objects.add(compact ? readArray(token, observer) : readFields(token));
        }
        return objects;
    }

    /** {@code [name, numbers..., {identity}]}: numbers or null in {@link CompactObject#NUMBERS}' order. */
    private SeenObject readArray(JsonToken start, Observer observer) throws IOException {
        in.expect(start, JsonToken.START_ARRAY, "an object array [name, dist, dir, ...]");
        String name = in.text(in.next());
        ObjectKind kind = CompactObject.kindOf(name);
        if (kind == null) {
            throw in.error("an object's name starts with b, g, f, l or p (ball, goal, flag, line, player), not '"
                    + name + "'");
        }
        Arrays.fill(numbers, Double.NaN);
        identity.clear();
        int index = 0;
        JsonToken token;
        while ((token = in.next()) != JsonToken.END_ARRAY) {
            if (token == JsonToken.START_OBJECT) {
                while (in.next() == JsonToken.FIELD_NAME) {
                    String field = in.fieldName();
                    if (!identityField(field, in.next())) {
                        in.skipChildren();
                    }
                }
                in.expect(in.next(), JsonToken.END_ARRAY, "the end of the object array after its identity");
                break;
            }
            if (index == numbers.length) {
                throw in.error("an object array holds at most " + numbers.length + " numbers after its name ("
                        + String.join(", ", CompactObject.NUMBERS) + ")");
            }
            if (token != JsonToken.VALUE_NULL) {
                numbers[index] = in.inRange(CompactObject.NUMBERS[index], in.number(token),
                        CompactObject.LOWEST[index], CompactObject.HIGHEST[index]);
            }
            index++;
        }
        Relation relation = identity.relation != null ? identity.relation
                : Relations.of(kind, name, identity.team, observer);
        return new SeenObject(kind, name, identity.team, identity.unum, identity.goalie, relation,
                numbers[0], numbers[1], numbers[2], numbers[3], numbers[4], numbers[5], numbers[6], identity.mark,
                grid.cell(numbers[0], numbers[1]));
    }

    /**
     * The fields an object has beside its name, numbers, kind and cell (format 3 keeps them in one
     * trailing object), one object at a time; a null relation is the one {@link Relations#of} derives.
     */
    private static final class Identity {
        String team;
        int unum;
        boolean goalie;
        Relation relation;
        char mark;

        void clear() {
            team = "";
            unum = 0;
            goalie = false;
            relation = null;
            mark = SeenObject.NO_MARK;
        }
    }

    /** Reads {@code field} into {@link #identity} when it is one of its fields; false when it is not. */
    private boolean identityField(String field, JsonToken value) throws IOException {
        switch (field) {
            case "team" -> identity.team = in.text(value);
            case "unum" -> identity.unum = in.intValue(value);
            case "goalie" -> identity.goalie = in.bool(value);
            case "relation" -> identity.relation = in.parseEnum(value, Relation::fromKey);
            case "mark" -> identity.mark = mark(value);
            default -> {
                return false;
            }
        }
        return true;
    }

    private char mark(JsonToken value) throws IOException {
        String text = in.text(value);
        if (!text.equals("t") && !text.equals("k")) {
            throw in.error("mark must be \"t\" or \"k\", not \"" + text + "\"");
        }
        return text.charAt(0);
    }

    /** Formats 1 and 2: {@code {"kind":..., "name":..., numbers by name, "cell":[column, row]}}. */
    private SeenObject readFields(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_OBJECT, "an object");
        ObjectKind kind = null;
        String name = null;
        Arrays.fill(numbers, Double.NaN);
        identity.clear();
        Cell cell = null;
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            int number = numberIndex(field);
            if (number >= 0) {
                numbers[number] = in.inRange(field, in.number(value), CompactObject.LOWEST[number],
                        CompactObject.HIGHEST[number]);
                continue;
            }
            if (identityField(field, value)) {
                continue;
            }
            switch (field) {
                case "kind" -> kind = in.parseEnum(value, ObjectKind::fromKey);
                case "name" -> name = in.text(value);
                case "cell" -> cell = readCell(value);
                default -> in.skipChildren();
            }
        }
        if (kind == null || name == null || name.isEmpty() || cell == null) {
            throw in.error("an object needs 'kind', 'name' and 'cell'");
        }
        // these formats write every relation but none
        Relation relation = identity.relation == null ? Relation.NONE : identity.relation;
        return new SeenObject(kind, name, identity.team, identity.unum, identity.goalie, relation, numbers[0],
                numbers[1], numbers[2], numbers[3], numbers[4], numbers[5], numbers[6], identity.mark, cell);
    }

    private static int numberIndex(String field) {
        for (int i = 0; i < CompactObject.NUMBERS.length; i++) {
            if (CompactObject.NUMBERS[i].equals(field)) {
                return i;
            }
        }
        return -1;
    }

    private Cell readCell(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_ARRAY, "a cell [column, row]");
        int column = in.intValue(in.next());
        int row = in.intValue(in.next());
        in.expect(in.next(), JsonToken.END_ARRAY, "the end of the cell [column, row]");
        if (column < 0 || column >= grid.columns() || row < 0 || row >= grid.rows()) {
            throw in.error("cell [" + column + ", " + row + "] lies outside the file's " + grid.describe() + " grid");
        }
        return new Cell(column, row);
    }
}
