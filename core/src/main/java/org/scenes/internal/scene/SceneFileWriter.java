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
 * Streams scenes into a scene file (see {@code docs/scene-format.md}), one scene per line.
 * Nothing appears at the target path until {@link #commit()}; closing without commit
 * discards what was written.
 */
public final class SceneFileWriter implements AutoCloseable {
    static final JsonFactory JSON = new JsonFactory();
    /** The fields and kinds of every object, encoded once (writing scenes is much of a conversion's time). */
    private static final SerializableString KIND = new SerializedString("kind");
    private static final SerializableString NAME = new SerializedString("name");
    private static final SerializableString CELL = new SerializedString("cell");
    private static final SerializableString TEAM = new SerializedString("team");
    private static final SerializableString UNUM = new SerializedString("unum");
    private static final SerializableString RELATION = new SerializedString("relation");
    private static final SerializableString AGE = new SerializedString("age");
    private static final SerializableString TYPE = new SerializedString("type");
    private static final SerializableString CYCLE = new SerializedString("cycle");
    private static final SerializableString DIST = new SerializedString("dist");
    private static final SerializableString DIR = new SerializedString("dir");
    private static final SerializableString DIST_CHANGE = new SerializedString("distChange");
    private static final SerializableString DIR_CHANGE = new SerializedString("dirChange");
    private static final SerializableString BODY_FACING = new SerializedString("bodyFacing");
    private static final SerializableString HEAD_FACING = new SerializedString("headFacing");
    private static final SerializableString POINT_DIR = new SerializedString("pointDir");
    private static final SerializableString X = new SerializedString("x");
    private static final SerializableString Y = new SerializedString("y");
    private static final SerializableString VX = new SerializedString("vx");
    private static final SerializableString VY = new SerializedString("vy");
    private static final SerializableString BODY = new SerializedString("body");
    private static final SerializableString NECK = new SerializedString("neck");
    private static final SerializableString STAMINA = new SerializedString("stamina");
    private static final SerializableString EFFORT = new SerializedString("effort");
    private static final SerializableString[] KINDS = new SerializableString[ObjectKind.values().length];
    private static final SerializableString[] RELATIONS = new SerializableString[Relation.values().length];
    private static final SerializableString[] ACTION_TYPES = new SerializableString[ActionType.values().length];
    /** Each action type's parameter names, by type and parameter. */
    private static final SerializableString[][] ACTION_PARAMETERS = new SerializableString[ActionType.values().length][];
    /** Distinct object names kept encoded; names beyond it (none in the server's protocol) are encoded each time. */
    private static final int NAMES_KEPT = 512;

    static {
        for (ObjectKind kind : ObjectKind.values()) {
            KINDS[kind.ordinal()] = new SerializedString(kind.key());
        }
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
            writeObject(object);
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

    private void writeObject(SeenObject object) throws IOException {
        json.writeStartObject();
        json.writeFieldName(KIND);
        json.writeString(KINDS[object.kind().ordinal()]);
        json.writeFieldName(NAME);
        writeKept(names, object.name());
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
        if (object.relation() != Relation.NONE) {
            json.writeFieldName(RELATION);
            json.writeString(RELATIONS[object.relation().ordinal()]);
        }
        writeOptional(DIST, object.distance());
        writeOptional(DIR, object.direction());
        writeOptional(DIST_CHANGE, object.distanceChange());
        writeOptional(DIR_CHANGE, object.directionChange());
        writeOptional(BODY_FACING, object.bodyFacing());
        writeOptional(HEAD_FACING, object.headFacing());
        writeOptional(POINT_DIR, object.pointingDirection());
        if (object.mark() != SeenObject.NO_MARK) {
            json.writeStringField("mark", String.valueOf(object.mark()));
        }
        json.writeFieldName(CELL);
        json.writeStartArray();
        json.writeNumber(object.cell().column());
        json.writeNumber(object.cell().row());
        json.writeEndArray();
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
            json.writeStartObject();
            json.writeFieldName(RELATION);
            json.writeString(RELATIONS[player.relation().ordinal()]);
            if (player.unum() > 0) {
                json.writeFieldName(UNUM);
                json.writeNumber(player.unum());
            }
            writeOptional(X, player.x());
            writeOptional(Y, player.y());
            json.writeFieldName(AGE);
            json.writeNumber(player.age());
            json.writeEndObject();
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

    private void writeOptional(SerializableString field, double value) throws IOException {
        if (Double.isNaN(value)) {
            return;
        }
        if (Double.isInfinite(value)) {
            // JSON has no infinity: written as a string, the file would be one its reader refuses
            throw new IllegalArgumentException("cannot write '" + field.getValue() + "' = " + value
                    + ": scene values are finite");
        }
        // whole numbers without ".0"; -0 keeps its sign, which the server's "-0" carries, as "-0.0"
        json.writeFieldName(field);
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
