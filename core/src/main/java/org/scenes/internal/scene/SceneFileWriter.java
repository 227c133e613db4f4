package org.scenes.internal.scene;

import com.fasterxml.jackson.core.JsonEncoding;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.SerializableString;
import com.fasterxml.jackson.core.io.SerializedString;
import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.World;
import org.scenes.internal.files.AtomicOutput;

/**
 * Streams scenes into a scene file of the current format (see {@code docs/scene-format.md}), one
 * scene per line.
 * Nothing appears at the target path until {@link #commit()}; closing without commit
 * discards what was written.
 */
public final class SceneFileWriter implements AutoCloseable {
    static final JsonFactory JSON = new JsonFactory();
    /** The fields and kinds of every object, encoded once (writing scenes is much of a conversion's time). */
    private static final SerializableString TEAM = new SerializedString("team");
    private static final SerializableString UNUM = new SerializedString("unum");
    private static final SerializableString RELATION = new SerializedString("relation");
    private static final SerializableString AGE = new SerializedString("age");
    private static final SerializableString TYPE = new SerializedString("type");
    private static final SerializableString CYCLE = new SerializedString("cycle");
    private static final SerializableString X = new SerializedString("x");
    private static final SerializableString Y = new SerializedString("y");
    private static final SerializableString VX = new SerializedString("vx");
    private static final SerializableString VY = new SerializedString("vy");
    private static final SerializableString BODY = new SerializedString("body");
    private static final SerializableString NECK = new SerializedString("neck");
    private static final SerializableString STAMINA = new SerializedString("stamina");
    private static final SerializableString EFFORT = new SerializedString("effort");
    private static final SerializableString[] RELATIONS = new SerializableString[Relation.values().length];
    private static final SerializableString[] ACTION_TYPES = new SerializableString[ActionType.values().length];
    /** Each action type's parameter names, by type and parameter. */
    private static final SerializableString[][] ACTION_PARAMETERS = new SerializableString[ActionType.values().length][];
    /** Distinct object names kept encoded; names beyond it (none in the server's protocol) are encoded each time. */
    private static final int NAMES_KEPT = 512;

    static {
        for (Relation relation : Relation.values()) {
            RELATIONS[relation.ordinal()] = new SerializedString(relation.key());
        }
        for (ActionType type : ActionType.values()) {
            ACTION_TYPES[type.ordinal()] = new SerializedString(type.key());
            ACTION_PARAMETERS[type.ordinal()] = new SerializableString[type.parameterCount()];
            for (int i = 0; i < type.parameterCount(); i++) {
                ACTION_PARAMETERS[type.ordinal()][i] = new SerializedString(type.parameter(i));
            }
        }
    }

    private final AtomicOutput output;
    private final JsonGenerator json;
    private final SceneFileHeader header;
    private long written;
    private final Map<String, SerializableString> names = new HashMap<>();
    /** Team names kept encoded, as object names (a game has two). */
    private final Map<String, SerializableString> teams = new HashMap<>();
    private final char[] number = new char[24];
    /** One object's numbers at a time. */
    private final double[] numbers = new double[CompactObject.NUMBERS.length];

    private SceneFileWriter(Path target, SceneFileHeader header) throws IOException {
        this.output = AtomicOutput.create(target);
        this.header = header;
        this.json = JSON.createGenerator(output.stream(), JsonEncoding.UTF8);
        writeHeader();
    }

    public static SceneFileWriter create(Path target, SceneFileHeader header) throws IOException {
        return new SceneFileWriter(target, header);
    }

    /** Writes a whole scene file in one step. */
    public static void write(Path target, SceneFile file) throws IOException {
        try (SceneFileWriter writer = create(target, file.header())) {
            for (Scene scene : file.scenes()) {
                writer.write(scene);
            }
            writer.commit();
        }
    }

    private void writeHeader() throws IOException {
        json.writeStartObject();
        json.writeNumberField("format", header.format());
        Grid grid = header.grid();
        json.writeRaw('\n');
        json.writeObjectFieldStart("grid");
        json.writeNumberField("columns", grid.columns());
        json.writeNumberField("rows", grid.rows());
        json.writeNumberField("minAngle", grid.minAngle());
        json.writeNumberField("maxAngle", grid.maxAngle());
        json.writeArrayFieldStart("bounds");
        for (double bound : grid.bounds()) {
            json.writeNumber(bound);
        }
        json.writeEndArray();
        json.writeEndObject();
        json.writeRaw('\n');
        json.writeObjectFieldStart("source");
        json.writeStringField("log", header.source().log());
        writeObserverFields(header.source().observer());
        if (header.source().goalie()) {
            json.writeBooleanField("goalie", true);
        }
        json.writeEndObject();
        json.writeRaw('\n');
        json.writeArrayFieldStart("scenes");
    }

    private void writeObserverFields(Observer observer) throws IOException {
        json.writeStringField("team", observer.team());
        if (observer.side() != null) {
            json.writeStringField("side", String.valueOf(observer.side().letter()));
        }
        if (observer.uniformNumber() > 0) {
            json.writeNumberField("unum", observer.uniformNumber());
        }
    }

    public void write(Scene scene) throws IOException {
        json.writeRaw('\n');
        json.writeStartObject();
        json.writeFieldName(CYCLE);
        json.writeNumber(scene.cycle());
        if (scene.seeAge() > 0) {
            json.writeNumberField("seeAge", scene.seeAge());
        }
        if (!scene.observer().equals(header.source().observer())) {
            json.writeObjectFieldStart("observer");
            writeObserverFields(scene.observer());
            json.writeEndObject();
        }
        json.writeArrayFieldStart("objects");
        for (SeenObject object : scene.objects()) {
            writeObject(object, scene.observer());
        }
        json.writeEndArray();
        json.writeArrayFieldStart("actions");
        List<Action> actions = scene.actions();
        for (int i = 0; i < actions.size(); i++) {
            writeAction(actions.get(i), i == 0);
        }
        json.writeEndArray();
        if (scene.world() != null) {
            writeWorld(scene.world());
        }
        json.writeEndObject();
        written++;
    }

    /**
     * Format 3's array {@code [name, numbers..., {identity}]} ({@link CompactObject}): unknown numbers
     * inside as null, at the end left out; the identity object only when there is one, its relation
     * only when the observer and the object's name and team do not imply it ({@link Relations#of}).
     */
    private void writeObject(SeenObject object, Observer observer) throws IOException {
        ObjectKind named = CompactObject.kindOf(object.name());
        if (named != object.kind()) {
            throw new IllegalArgumentException("cannot write object '" + object.name() + "' of kind "
                    + object.kind().key() + ": scene files tell an object's kind by its name's first letter");
        }
        if (!object.cell().equals(header.grid().cell(object.distance(), object.direction()))) {
            throw new IllegalArgumentException("cannot write object '" + object.name() + "' in cell "
                    + object.cell() + ": scene files hold the cell of its distance and direction in the file's grid");
        }
        json.writeStartArray();
        writeKept(names, object.name());
        CompactObject.numbers(object, numbers);
        int last = numbers.length - 1;
        while (last >= 0 && Double.isNaN(numbers[last])) {
            last--;
        }
        for (int i = 0; i <= last; i++) {
            writeNumberOrNull(CompactObject.NUMBERS[i], numbers[i]);
        }
        boolean relation = object.relation() != Relations.of(object.kind(), object.name(), object.team(), observer);
        if (relation || !object.team().isEmpty() || object.uniformNumber() > 0 || object.goalie()
                || object.mark() != SeenObject.NO_MARK) {
            writeIdentity(object, relation);
        }
        json.writeEndArray();
    }

    private void writeIdentity(SeenObject object, boolean relation) throws IOException {
        json.writeStartObject();
        if (!object.team().isEmpty()) {
            json.writeFieldName(TEAM);
            writeKept(teams, object.team());
        }
        if (object.uniformNumber() > 0) {
            json.writeFieldName(UNUM);
            json.writeNumber(object.uniformNumber());
        }
        if (object.goalie()) {
            json.writeBooleanField("goalie", true);
        }
        if (relation) {
            json.writeFieldName(RELATION);
            json.writeString(RELATIONS[object.relation().ordinal()]);
        }
        if (object.mark() != SeenObject.NO_MARK) {
            json.writeStringField("mark", String.valueOf(object.mark()));
        }
        json.writeEndObject();
    }

    /** {@code text} as a JSON string, encoded once per distinct text while {@code kept} has room. */
    private void writeKept(Map<String, SerializableString> kept, String text) throws IOException {
        SerializableString encoded = kept.get(text);
        if (encoded == null && kept.size() < NAMES_KEPT) {
            encoded = new SerializedString(text);
            kept.put(text, encoded);
        }
        if (encoded != null) {
            json.writeString(encoded);
        } else {
            json.writeString(text);
        }
    }

    /** The scene's world model (format 2): values not known are left out. */
    private void writeWorld(World world) throws IOException {
        json.writeObjectFieldStart("world");
        writeOptional(X, world.x());
        writeOptional(Y, world.y());
        writeOptional(BODY, world.body());
        writeOptional(NECK, world.neck());
        writeOptional(VX, world.vx());
        writeOptional(VY, world.vy());
        writeOptional(STAMINA, world.stamina());
        writeOptional(EFFORT, world.effort());
        if (world.age() >= 0) {
            json.writeFieldName(AGE);
            json.writeNumber(world.age());
        }
        if (world.ballAge() >= 0) {
            json.writeObjectFieldStart("ball");
            writeOptional(X, world.ballX());
            writeOptional(Y, world.ballY());
            writeOptional(VX, world.ballVx());
            writeOptional(VY, world.ballVy());
            json.writeFieldName(AGE);
            json.writeNumber(world.ballAge());
            json.writeEndObject();
        }
        json.writeArrayFieldStart("players");
        for (World.Player player : world.players()) {
            json.writeStartArray();
            json.writeString(RELATIONS[player.relation().ordinal()]);
            if (player.unum() > 0) {
                json.writeNumber(player.unum());
            } else {
                json.writeNull();
            }
            writeNumberOrNull("x", player.x());
            writeNumberOrNull("y", player.y());
            json.writeNumber(player.age());
            json.writeEndArray();
        }
        json.writeEndArray();
        if (!world.playMode().isEmpty()) {
            json.writeStringField("playMode", world.playMode());
        }
        json.writeArrayFieldStart("score");
        json.writeNumber(world.ownScore());
        json.writeNumber(world.opponentScore());
        json.writeEndArray();
        json.writeEndObject();
    }

    private void writeAction(Action action, boolean primary) throws IOException {
        json.writeStartObject();
        json.writeFieldName(TYPE);
        int type = action.type().ordinal();
        json.writeString(ACTION_TYPES[type]);
        for (int i = 0; i < ACTION_PARAMETERS[type].length; i++) {
            writeOptional(ACTION_PARAMETERS[type][i], action.parameter(i));
        }
        if (primary) {
            json.writeBooleanField("primary", true);
        }
        json.writeEndObject();
    }

    /** A named field for a known value, nothing for NaN. */
    private void writeOptional(SerializableString field, double value) throws IOException {
        if (Double.isNaN(value)) {
            return;
        }
        json.writeFieldName(field);
        writeNumber(field.getValue(), value);
    }

    /** A value in an array: null for NaN. */
    private void writeNumberOrNull(String what, double value) throws IOException {
        if (Double.isNaN(value)) {
            json.writeNull();
        } else {
            writeNumber(what, value);
        }
    }

    /** A finite value, {@code what} naming it should it not be. */
    private void writeNumber(String what, double value) throws IOException {
        if (Double.isInfinite(value)) {
            // JSON has no infinity: written as a string, the file would be one its reader refuses
            throw new IllegalArgumentException("cannot write '" + what + "' = " + value + ": scene values are finite");
        }
        // whole numbers without ".0"; -0 keeps its sign, which the server's "-0" carries, as "-0.0"
        if (value == Math.rint(value) && Math.abs(value) < 1e15
                && Double.doubleToRawLongBits(value) != Double.doubleToRawLongBits(-0.0)) {
            json.writeNumber((long) value);
            return;
        }
        // Most values are tenths (distances, changes) or hundredths (world models): their text as
        // Double.toString writes it, cheaper. JDK 17's Double.toString gives every hundredth below
        // 10^6 in magnitude its two decimals (all of them checked once; SceneFileWriterTest a sample).
        double tenths = Math.rint(value * 10);
        if (tenths != 0 && Math.abs(tenths) < 1e7 && tenths / 10 == value) {
            json.writeNumber(number, 0, decimals((long) tenths, 1));
            return;
        }
        double hundredths = Math.rint(value * 100);
        if (hundredths != 0 && Math.abs(hundredths) < 1e8 && hundredths / 100 == value) {
            json.writeNumber(number, 0, decimals((long) hundredths, 2));
        } else {
            json.writeNumber(value);
        }
    }

    /**
     * {@code scaled / 10^places} with {@code places} decimals (1 or 2) into {@link #number}, as
     * {@link Double#toString} writes such a value; returns its length.
     */
    private int decimals(long scaled, int places) {
        int at = number.length;
        long rest = Math.abs(scaled);
        for (int i = 0; i < places; i++) {
            number[--at] = (char) ('0' + rest % 10);
            rest /= 10;
        }
        number[--at] = '.';
        do {
            number[--at] = (char) ('0' + rest % 10);
            rest /= 10;
        } while (rest > 0);
        if (scaled < 0) {
            number[--at] = '-';
        }
        int length = number.length - at;
        System.arraycopy(number, at, number, 0, length);
        return length;
    }

    public long written() {
        return written;
    }

    /** Ends the JSON document and moves the file into place. */
    public void commit() throws IOException {
        json.writeRaw('\n');
        json.writeEndArray();
        json.writeEndObject();
        json.writeRaw('\n');
        json.close();
        output.commit();
    }

    @Override
    public void close() throws IOException {
        output.close();
    }
}
