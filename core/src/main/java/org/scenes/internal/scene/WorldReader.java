package org.scenes.internal.scene;

import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.scenes.api.Relation;
import org.scenes.api.World;

/**
 * Reads a scene's {@code world} block (formats 2 and 3); values left out are unknown (NaN, age -1).
 * Its players are arrays {@code [relation, unum, x, y, age]} in format 3, objects with those fields
 * in format 2.
 */
final class WorldReader {
    /** The world block's own numbers, in {@link World}'s order. */
    private static final List<String> NUMBERS = List.of("x", "y", "body", "neck", "vx", "vy", "stamina", "effort");

    private final SceneJson in;
    private final boolean compact;

    WorldReader(SceneJson in, int format) {
        this.in = in;
        this.compact = format >= 3;
    }

    World read(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_OBJECT, "a world object");
        double[] self = {Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN};
        double[] ball = {Double.NaN, Double.NaN, Double.NaN, Double.NaN};
        int age = -1;
        int ballAge = -1;
        List<World.Player> players = new ArrayList<>();
        String playMode = "";
        int own = 0;
        int opponent = 0;
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            int index = NUMBERS.indexOf(field);
            if (index >= 0) {
                self[index] = in.number(value);
                continue;
            }
            switch (field) {
                case "age" -> age = in.intValue(value);
                case "ball" -> ballAge = readBall(value, ball);
                case "players" -> {
                    in.expect(value, JsonToken.START_ARRAY, "an array of players");
                    while (in.next() != JsonToken.END_ARRAY) {
                        JsonToken player = in.json.currentToken();
                        players.add(compact ? readPlayerArray(player) : readPlayerFields(player));
                    }
                }
                case "playMode" -> playMode = in.text(value);
                case "score" -> {
                    in.expect(value, JsonToken.START_ARRAY, "a score [own, opponent]");
                    own = in.intValue(in.next());
                    opponent = in.intValue(in.next());
                    in.expect(in.next(), JsonToken.END_ARRAY, "the end of the score [own, opponent]");
                }
                default -> in.skipChildren();
            }
        }
        return new World(self[0], self[1], self[2], self[3], self[4], self[5], self[6], self[7], age,
                ball[0], ball[1], ball[2], ball[3], ballAge, players, playMode, own, opponent);
    }

    /** The ball's position and velocity into {@code ball}; returns its age. */
    private int readBall(JsonToken start, double[] ball) throws IOException {
        in.expect(start, JsonToken.START_OBJECT, "a ball object");
        int age = -1;
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            switch (field) {
                case "x" -> ball[0] = in.number(value);
                case "y" -> ball[1] = in.number(value);
                case "vx" -> ball[2] = in.number(value);
                case "vy" -> ball[3] = in.number(value);
                case "age" -> age = in.intValue(value);
                default -> in.skipChildren();
            }
        }
        return age;
    }

    /** Format 3: {@code [relation, unum or null, x, y, age]}. */
    private World.Player readPlayerArray(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_ARRAY, "a player array [relation, unum, x, y, age]");
        Relation relation = in.parseEnum(in.next(), Relation::fromKey);
        JsonToken unumToken = in.next();
        int unum = unumToken == JsonToken.VALUE_NULL ? 0 : in.intValue(unumToken);
        double x = numberOrNull(in.next());
        double y = numberOrNull(in.next());
        int age = in.intValue(in.next());
        in.expect(in.next(), JsonToken.END_ARRAY, "the end of the player array [relation, unum, x, y, age]");
        return new World.Player(relation, unum, x, y, age);
    }

    private double numberOrNull(JsonToken value) throws IOException {
        return value == JsonToken.VALUE_NULL ? Double.NaN : in.number(value);
    }

    /** Format 2: {@code {"relation":..., "unum":..., "x":..., "y":..., "age":...}}. */
    private World.Player readPlayerFields(JsonToken start) throws IOException {
        in.expect(start, JsonToken.START_OBJECT, "a player object");
        Relation relation = Relation.UNKNOWN;
        int unum = 0;
        double x = Double.NaN;
        double y = Double.NaN;
        int age = 0;
        while (in.next() == JsonToken.FIELD_NAME) {
            String field = in.fieldName();
            JsonToken value = in.next();
            switch (field) {
                case "relation" -> relation = in.parseEnum(value, Relation::fromKey);
                case "unum" -> unum = in.intValue(value);
                case "x" -> x = in.number(value);
                case "y" -> y = in.number(value);
                case "age" -> age = in.intValue(value);
                default -> in.skipChildren();
            }
        }
        return new World.Player(relation, unum, x, y, age);
    }
}
