package org.scenes.internal.match;

import static org.scenes.internal.match.ObjectSetMetric.GROUPS;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.match.ObjectSetMetric.Encoded;
import org.scenes.internal.match.ObjectSetMetric.Settings;

/**
 * Places a scene's objects as {@link ObjectSetMetric} compares them: per weighted group, nearest
 * first, the floats of {@link Encoded}; with memory, the previous scene and the remembered action
 * classes too. The metric's layout (stride, where the penalty and the additive coordinates are)
 * comes from it.
 */
final class ObjectSetEncoder {
    /** The group of all players; the player classes' groups follow it. */
    private static final int PLAYERS = 6;
    static final int[] NO_ACTIONS = new int[0];

    private final Settings settings;
    private final double[] groupWeight;
    private final int stride;
    private final int penaltyAt;
    private final int additiveAt;
    private final boolean rows;
    private final boolean sides;

    ObjectSetEncoder(Settings settings, double[] groupWeight, int stride, int penaltyAt, int additiveAt, boolean rows, boolean sides) {
        this.settings = settings;
        this.groupWeight = groupWeight;
        this.stride = stride;
        this.penaltyAt = penaltyAt;
        this.additiveAt = additiveAt;
        this.rows = rows;
        this.sides = sides;
    }

    /** Whether a group holds players (all, teammates, opponents, unknown): with nearest-players, its nearest only. */
    private static boolean playerGroup(int group) {
        return group >= PLAYERS;
    }

    /** One object in the configured space, as stored, and the distance it is sorted by. */
    private record Placed(double distance, float a, float b, float penalty, float row, float sideX, float sideY) {
    }

    private static final Comparator<Placed> NEAREST_FIRST = Comparator.comparingDouble(Placed::distance);
    /** The encoding of an empty group, shared (encodings are never written to). */
    private static final float[] NO_OBJECTS = new float[0];

    /**
     * The remembered previous scene as the memory term compares it: as {@link #encode(Scene, boolean)}
     * without memory, but with memory-direction-weight, since the direction that tells a turn from a dash
     * now may be noise one scene back.
     */
    Encoded encodePrevious(Scene previous) {
        return encode(previous, false, settings.memoryDirectionWeight(), settings.memoryRowWeight());
    }

    Encoded encode(Scene scene, boolean withMemory) {
        return encode(scene, withMemory, settings.directionWeight(), settings.rowWeight());
    }

    private Encoded encode(Scene scene, boolean withMemory, double directionWeight, double rowWeight) {
        if (scene == null) {
            return new Encoded(new float[GROUPS][0], null, NO_ACTIONS);
        }
        // lists only for weighted groups: the others stay empty (a query is encoded on every decision)
        List<List<Placed>> groups = new ArrayList<>(GROUPS);
        for (int group = 0; group < GROUPS; group++) {
            groups.add(groupWeight[group] > 0 ? new ArrayList<>() : null);
        }
        for (SeenObject object : scene.objects()) {
            int group = groupOf(object);
            if (groupWeight[group] > 0) {
                groups.get(group).add(place(object, directionWeight, rowWeight));
            }
            if (object.kind() == ObjectKind.PLAYER && groupWeight[PLAYERS] > 0) {
                groups.get(PLAYERS).add(place(object, directionWeight, rowWeight));
            }
        }
        float[][] packed = new float[GROUPS][];
        for (int group = 0; group < GROUPS; group++) {
            List<Placed> objects = groups.get(group);
            if (objects == null || objects.isEmpty()) {
                packed[group] = NO_OBJECTS;
                continue;
            }
            objects.sort(NEAREST_FIRST);
            int kept = settings.nearestPlayers() && playerGroup(group) ? Math.min(1, objects.size()) : objects.size();
            float[] values = new float[kept * stride];
            for (int i = 0; i < kept; i++) {
                Placed object = objects.get(i);
                int at = i * stride;
                values[at] = object.a();
                values[at + 1] = object.b();
                if (penaltyAt >= 0) {
                    values[at + penaltyAt] = object.penalty();
                }
                int additive = at + additiveAt;
                if (rows) {
                    values[additive++] = object.row();
                }
                if (sides) {
                    values[additive] = object.sideX();
                    values[additive + 1] = object.sideY();
                }
            }
            packed[group] = values;
        }
        boolean remember = withMemory && (settings.memoryWeight() > 0 || settings.memoryActionWeight() > 0);
        Encoded previous = remember && settings.memoryWeight() > 0 ? encodePrevious(scene.previous()) : null;
        return new Encoded(packed, previous, remember ? rememberedActions(scene) : NO_ACTIONS);
    }


    /** The action classes 1 .. memory-depth scenes back (-1 past the start of the remembered chain). */
    int[] rememberedActions(Scene scene) {
        if (settings.memoryActionWeight() == 0) {
            return NO_ACTIONS;
        }
        int[] classes = new int[settings.memoryDepth()];
        Scene earlier = scene.previous();
        for (int i = 0; i < classes.length; i++) {
            classes[i] = earlier == null ? -1 : ObjectSetMetric.actionClass(earlier);
            earlier = earlier == null ? null : earlier.previous();
        }
        return classes;
    }

    /** Objects per group as {@link #encode} stores them, without placing them. */
    void count(Scene scene, int[] counts) {
        Arrays.fill(counts, 0);
        for (SeenObject object : scene.objects()) {
            int group = groupOf(object);
            if (groupWeight[group] > 0) {
                counts[group]++;
            }
            if (object.kind() == ObjectKind.PLAYER && groupWeight[PLAYERS] > 0) {
                counts[PLAYERS]++;
            }
        }
        if (settings.nearestPlayers()) {
            for (int group = PLAYERS; group < GROUPS; group++) {
                counts[group] = Math.min(1, counts[group]);
            }
        }
    }

    private static int groupOf(SeenObject object) {
        return switch (object.kind()) {
            case BALL -> 0;
            case GOAL -> object.relation() == Relation.OWN ? 1 : object.relation() == Relation.OPPONENT ? 2 : 3;
            case FLAG -> 4;
            case LINE -> 5;
            case PLAYER -> object.relation() == Relation.TEAMMATE ? 7 : object.relation() == Relation.OPPONENT ? 8 : 9;
        };
    }

    /** (a, b, penalty, weighted row) of one object in the configured space, rounded to floats. */
    private Placed place(SeenObject object, double directionWeight, double rowWeight) {
        double r = object.distance();
        double direction = Double.isNaN(object.direction()) ? 0 : object.direction();
        if (settings.projectCycles() != 0) {
            if (!Double.isNaN(object.distanceChange()) && !Double.isNaN(r)) {
                r = Math.max(0, r + settings.projectCycles() * object.distanceChange());
            }
            if (!Double.isNaN(object.directionChange())) {
                direction += settings.projectCycles() * object.directionChange();
            }
        }
        if (Double.isNaN(r)) {
            r = 100; // not sent: as far as the field allows
        }
        double radial = settings.logDistance() ? Math.log1p(r) : r;
        double a;
        double b;
        double penaltyDistance = r;
        switch (settings.space()) {
            case CARTESIAN -> {
                double radians = Math.toRadians(direction);
                a = radial * Math.cos(radians);
                b = radial * Math.sin(radians);
            }
            case POLAR -> {
                a = settings.distanceWeight() * radial;
                b = directionWeight * direction;
            }
            default -> {
                a = object.cell().column();
                b = object.cell().row();
                penaltyDistance = object.cell().row();
            }
        }
        double l = settings.penaltyScale();
        double penalty = settings.penalty() * l / (l + penaltyDistance);
        // left (0, 0), ahead (ws/2, ws/2), right (ws, 0): every two sides ws apart in |dx| + |dy|
        double side = settings.sideWeight();
        boolean ahead = Math.abs(direction) < settings.aheadWidth() / 2;
        float sideX = (float) (ahead ? side / 2 : direction > 0 ? side : 0);
        float sideY = (float) (ahead ? side / 2 : 0);
        return new Placed(r, (float) a, (float) b, (float) penalty, (float) (rowWeight * object.cell().row()),
                sideX, sideY);
    }
}
