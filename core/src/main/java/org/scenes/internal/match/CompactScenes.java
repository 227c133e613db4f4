package org.scenes.internal.match;

import java.util.AbstractList;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.RandomAccess;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.World;

/**
 * Scenes held as one byte stream instead of objects: a knowledge base of a million scenes as
 * {@link Scene} records would take gigabytes (a record per seen object, eight doubles each),
 * while the values the server sends are short decimals. Lossless: every double is stored as a
 * variable-length integer with 0, 1 or 2 decimals when that gives back exactly the same bits,
 * otherwise as its 8 raw bytes; an object's class, name and present fields are one interned
 * "shape", observers and team names are interned too; a cell is stored only when
 * it is not the one the grid gives for the object's distance and direction. Scenes are decoded
 * anew on each access. Appending is single-threaded; once built, reading is thread-safe.
 */
final class CompactScenes extends AbstractList<Scene> implements RandomAccess {
    private static final ActionType[] ACTION_TYPES = ActionType.values();
    private static final Relation[] RELATIONS = Relation.values();
    private static final double[] SCALES = {1, 10, 100};
    private static final int RAW = 3;
    /** The tagged value of the plain NaN ("not sent"): the raw tag with payload 1. */
    private static final int NOT_SENT = 1 << 2 | RAW;

    // presence bits of an object: which numeric fields follow, and the optional ones
    private static final int DISTANCE = 1;
    private static final int DIRECTION = 1 << 1;
    private static final int DISTANCE_CHANGE = 1 << 2;
    private static final int DIRECTION_CHANGE = 1 << 3;
    private static final int BODY_FACING = 1 << 4;
    private static final int HEAD_FACING = 1 << 5;
    private static final int POINTING = 1 << 6;
    private static final int PLAYER_DETAILS = 1 << 7;
    private static final int EXPLICIT_CELL = 1 << 8;
    /** a remembered object's confidence follows (below 1) */
    private static final int CONFIDENCE = 1 << 9;

    private final Grid grid;
    private final List<String> strings = new ArrayList<>();
    private final Map<String, Integer> stringIndex = new HashMap<>();
    private final List<Shape> shapes = new ArrayList<>();
    private final Map<Shape, Integer> shapeIndex = new HashMap<>();
    private final List<Observer> observers = new ArrayList<>();
    private final Map<Observer, Integer> observerIndex = new HashMap<>();
    // scenes in chunks, so growing never needs a second copy of everything; no scene spans two.
    // 256 KB: below the size at which G1 gives an array whole regions of its own
    private static final int CHUNK_BITS = 18;
    private static final int CHUNK = 1 << CHUNK_BITS;
    private final List<byte[]> chunks = new ArrayList<>();
    private int chunkLength = CHUNK;
    private long storedBytes;
    /** the scene being written, copied into a chunk once whole */
    private byte[] pending = new byte[1 << 12];
    private int length;
    /** per scene: chunk index and offset in it, as chunk << CHUNK_BITS | offset */
    private int[] starts = new int[64];
    private int size;

    /**
     * What objects of a scene share: class, name, marks and which fields were sent. A few dozen
     * shapes cover a whole game (one per flag, line, goal, ...), so an object starts with one byte.
     */
    private record Shape(ObjectKind kind, Relation relation, String name, boolean goalie, char mark, int presence) {
    }

    CompactScenes(Grid grid) {
        this.grid = grid;
    }

    void append(Scene scene) {
        if (size == starts.length) {
            starts = Arrays.copyOf(starts, starts.length * 2);
        }
        length = 0;
        writeScene(scene);
        if (length > CHUNK) {
            throw new IllegalArgumentException("scene " + scene.cycle() + " is too large to store: "
                    + scene.objects().size() + " objects");
        }
        if (chunkLength + length > CHUNK) {
            if (chunks.size() == 1 << (31 - CHUNK_BITS)) {
                throw new IllegalStateException("a knowledge base holds at most 2 GB of packed scenes; "
                        + size + " scenes fill it");
            }
            chunks.add(new byte[CHUNK]);
            chunkLength = 0;
        }
        System.arraycopy(pending, 0, chunks.get(chunks.size() - 1), chunkLength, length);
        starts[size] = (chunks.size() - 1) << CHUNK_BITS | chunkLength;
        chunkLength += length;
        storedBytes += length;
        size++;
    }

    /** Bytes held for scene data, for memory reports. */
    long storedBytes() {
        return storedBytes + 4L * size;
    }

    /** Drops the spare capacity once no scene will be appended. */
    void trim() {
        if (!chunks.isEmpty()) {
            chunks.set(chunks.size() - 1, Arrays.copyOf(chunks.get(chunks.size() - 1), chunkLength));
        }
        starts = Arrays.copyOf(starts, size);
    }

    @Override
    public Scene get(int index) {
        return reader(index).scene();
    }

    /** The cycle of a scene, read without decoding the rest of it. */
    int cycle(int index) {
        return reader(index).cycle();
    }

    /** The see age of a scene, read without decoding the rest of it. */
    int seeAge(int index) {
        return reader(index).seeAge();
    }

    /** A reader at the start of scene {@code index}. */
    private Reader reader(int index) {
        if (index < 0 || index >= size) {
            throw new IndexOutOfBoundsException("scene " + index + " of " + size);
        }
        int start = starts[index];
        return new Reader(chunks.get(start >>> CHUNK_BITS), start & CHUNK - 1);
    }

    @Override
    public int size() {
        return size;
    }

    private void writeScene(Scene scene) {
        writeVarint(zigzag(scene.cycle()));
        int observer = observerIndex.computeIfAbsent(scene.observer(), o -> {
            observers.add(o);
            return observers.size() - 1;
        });
        // the low bit says whether a see age follows, so scenes of their own cycle's see cost nothing more
        writeVarint((long) observer << 1 | (scene.seeAge() > 0 ? 1 : 0));
        if (scene.seeAge() > 0) {
            writeVarint(scene.seeAge());
        }
        writeVarint(scene.actions().size());
        for (Action action : scene.actions()) {
            writeVarint(action.type().ordinal());
            writeValue(action.first());
            writeValue(action.second());
        }
        writeVarint(scene.objects().size());
        for (SeenObject object : scene.objects()) {
            writeObject(object);
        }
        writeWorld(scene.world());
        if (scene.previous() == null) {
            writeVarint(0);
        } else {
            writeVarint(1);
            writeScene(scene.previous());
        }
    }

    /** A world model (0 for none, else 1 and its values; positions to the centimetre pack in a few bytes). */
    private void writeWorld(World world) {
        if (world == null) {
            writeVarint(0);
            return;
        }
        writeVarint(1);
        for (double value : new double[] {world.x(), world.y(), world.body(), world.neck(), world.vx(), world.vy(),
            world.stamina(), world.effort(), world.ballX(), world.ballY(), world.ballVx(), world.ballVy()}) {
            writeValue(value);
        }
        writeVarint(zigzag(world.age()));
        writeVarint(zigzag(world.ballAge()));
        writeVarint(intern(world.playMode()));
        writeVarint(world.ownScore());
        writeVarint(world.opponentScore());
        writeVarint(world.players().size());
        for (World.Player player : world.players()) {
            writeVarint(player.relation().ordinal());
            writeVarint(player.unum());
            writeValue(player.x());
            writeValue(player.y());
            writeVarint(player.age());
        }
    }

    private void writeObject(SeenObject object) {
        double[] values = {object.distance(), object.direction(), object.distanceChange(), object.directionChange(),
            object.bodyFacing(), object.headFacing(), object.pointingDirection()};
        int presence = 0;
        for (int i = 0; i < values.length; i++) {
            if (!isPlainNaN(values[i])) {
                presence |= 1 << i;
            }
        }
        boolean details = !object.team().isEmpty() || object.uniformNumber() != 0;
        if (details) {
            presence |= PLAYER_DETAILS;
        }
        boolean explicitCell = !object.cell().equals(grid.cell(object.distance(), object.direction()));
        if (explicitCell) {
            presence |= EXPLICIT_CELL;
        }
        if (object.remembered()) {
            presence |= CONFIDENCE;
        }
        Shape shape = new Shape(object.kind(), object.relation(), object.name(), object.goalie(), object.mark(), presence);
        writeVarint(shapeIndex.computeIfAbsent(shape, key -> {
            shapes.add(key);
            return shapes.size() - 1;
        }));
        if (details) {
            writeVarint(intern(object.team()));
            writeVarint(zigzag(object.uniformNumber()));
        }
        for (int i = 0; i < values.length; i++) {
            if ((presence & 1 << i) != 0) {
                writeValue(values[i]);
            }
        }
        if (explicitCell) {
            writeVarint(object.cell().column());
            writeVarint(object.cell().row());
        }
        if (object.remembered()) {
            writeValue(object.confidence());
        }
    }

    /** The NaN that means "not sent"; any other NaN payload is kept as raw bits. */
    private static boolean isPlainNaN(double value) {
        return Double.doubleToRawLongBits(value) == Double.doubleToRawLongBits(Double.NaN);
    }

    private int intern(String text) {
        return stringIndex.computeIfAbsent(text, key -> {
            strings.add(key);
            return strings.size() - 1;
        });
    }

    /** A value as a tagged integer with 0, 1 or 2 decimals when that is exact to the bit, else raw. */
    private void writeValue(double value) {
        if (isPlainNaN(value)) {
            writeVarint(NOT_SENT);
            return;
        }
        long bits = Double.doubleToRawLongBits(value);
        for (int tag = 0; tag < SCALES.length; tag++) {
            double scaled = value * SCALES[tag];
            if (Math.abs(scaled) < 1e15) {
                long integer = Math.round(scaled);
                if (Double.doubleToRawLongBits(integer / SCALES[tag]) == bits) {
                    writeVarint(zigzag(integer) << 2 | tag);
                    return;
                }
            }
        }
        writeVarint(RAW);
        for (int shift = 0; shift < 64; shift += 8) {
            writeByte((int) (bits >>> shift));
        }
    }

    private static long zigzag(long value) {
        return value << 1 ^ value >> 63;
    }

    private void writeVarint(long value) {
        while ((value & ~0x7FL) != 0) {
            writeByte((int) (value & 0x7F) | 0x80);
            value >>>= 7;
        }
        writeByte((int) value);
    }

    private void writeByte(int value) {
        if (length == pending.length) {
            pending = Arrays.copyOf(pending, pending.length * 2);
        }
        pending[length++] = (byte) value;
    }

    /** Decodes from one position; one per access, so reading needs no lock. */
    private final class Reader {
        private final byte[] bytes;
        private int position;

        Reader(byte[] chunk, int position) {
            this.bytes = chunk;
            this.position = position;
        }

        /** The cycle, a scene's first field. */
        int cycle() {
            return (int) unzigzag(varint());
        }

        /** The see age at the start of a scene, from its first two fields. */
        int seeAge() {
            varint(); // the cycle
            return (varint() & 1) == 1 ? (int) varint() : 0;
        }

        Scene scene() {
            int cycle = (int) unzigzag(varint());
            long observerAndAge = varint();
            Observer observer = observers.get((int) (observerAndAge >>> 1));
            int seeAge = (observerAndAge & 1) == 1 ? (int) varint() : 0;
            int actionCount = (int) varint();
            List<Action> actions = new ArrayList<>(actionCount);
            for (int i = 0; i < actionCount; i++) {
                ActionType type = ACTION_TYPES[(int) varint()];
                double first = value();
                actions.add(new Action(type, first, value()));
            }
            int objectCount = (int) varint();
            List<SeenObject> objects = new ArrayList<>(objectCount);
            for (int i = 0; i < objectCount; i++) {
                objects.add(object());
            }
            World world = varint() == 1 ? world() : null;
            Scene previous = varint() == 1 ? scene() : null;
            return new Scene(cycle, observer, objects, actions, previous, seeAge, world);
        }

        private World world() {
            double[] v = new double[12];
            for (int i = 0; i < v.length; i++) {
                v[i] = value();
            }
            int age = (int) unzigzag(varint());
            int ballAge = (int) unzigzag(varint());
            String playMode = strings.get((int) varint());
            int own = (int) varint();
            int opponent = (int) varint();
            int count = (int) varint();
            List<World.Player> players = new ArrayList<>(count);
            for (int i = 0; i < count; i++) {
                Relation relation = RELATIONS[(int) varint()];
                int unum = (int) varint();
                double x = value();
                double y = value();
                players.add(new World.Player(relation, unum, x, y, (int) varint()));
            }
            return new World(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], age, v[8], v[9], v[10], v[11], ballAge,
                    players, playMode, own, opponent);
        }

        private SeenObject object() {
            Shape shape = shapes.get((int) varint());
            int presence = shape.presence();
            String team = "";
            int uniformNumber = 0;
            if ((presence & PLAYER_DETAILS) != 0) {
                team = strings.get((int) varint());
                uniformNumber = (int) unzigzag(varint());
            }
            // seven fields in the order written, as locals: no array per decoded object
            double distance = optional(presence, DISTANCE);
            double direction = optional(presence, DIRECTION);
            double distanceChange = optional(presence, DISTANCE_CHANGE);
            double directionChange = optional(presence, DIRECTION_CHANGE);
            double bodyFacing = optional(presence, BODY_FACING);
            double headFacing = optional(presence, HEAD_FACING);
            double pointing = optional(presence, POINTING);
            Cell cell = (presence & EXPLICIT_CELL) != 0 ? new Cell((int) varint(), (int) varint())
                    : grid.cell(distance, direction);
            double confidence = (presence & CONFIDENCE) != 0 ? value() : 1;
            return new SeenObject(shape.kind(), shape.name(), team, uniformNumber, shape.goalie(), shape.relation(),
                    distance, direction, distanceChange, directionChange, bodyFacing, headFacing, pointing, shape.mark(), cell,
                    confidence);
        }

        private double optional(int presence, int field) {
            return (presence & field) != 0 ? value() : Double.NaN;
        }

        private double value() {
            long tagged = varint();
            int tag = (int) (tagged & 3);
            if (tag != RAW) {
                return unzigzag(tagged >>> 2) / SCALES[tag];
            }
            if (tagged == NOT_SENT) {
                return Double.NaN;
            }
            long bits = 0;
            for (int shift = 0; shift < 64; shift += 8) {
                bits |= (bytes[position++] & 0xFFL) << shift;
            }
            return Double.longBitsToDouble(bits);
        }

        private long varint() {
            long value = 0;
            int shift = 0;
            byte b;
            do {
                b = bytes[position++];
                value |= (long) (b & 0x7F) << shift;
                shift += 7;
            } while (b < 0);
            return value;
        }
    }

    private static long unzigzag(long value) {
        return value >>> 1 ^ -(value & 1);
    }
}
