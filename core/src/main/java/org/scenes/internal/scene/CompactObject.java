package org.scenes.internal.scene;

import org.scenes.api.ObjectKind;
import org.scenes.api.SeenObject;

/**
 * The array form of a seen object in scene files of format 3:
 * {@code [name, dist, dir, distChange, dirChange, bodyFacing, headFacing, pointDir, {identity}]}.
 * The kind is the name's first letter and the cell follows from the file's grid, so neither is
 * written; a scene is about a fifth of its format-2 size, which is most of what converting costs.
 */
final class CompactObject {
    /** The numbers' names, in their order after the name (as the server lists them in a see). */
    static final String[] NUMBERS = {"dist", "dir", "distChange", "dirChange", "bodyFacing", "headFacing", "pointDir"};
    /** The lowest and highest value of each number, as {@link SceneValues} allows them. */
    static final double[] LOWEST = {0, -SceneValues.MAX_DIRECTION, -SceneValues.MAX_CHANGE, -SceneValues.MAX_CHANGE,
        -SceneValues.MAX_DIRECTION, -SceneValues.MAX_DIRECTION, -SceneValues.MAX_DIRECTION};
    static final double[] HIGHEST = {SceneValues.MAX_DISTANCE, SceneValues.MAX_DIRECTION, SceneValues.MAX_CHANGE,
        SceneValues.MAX_CHANGE, SceneValues.MAX_DIRECTION, SceneValues.MAX_DIRECTION, SceneValues.MAX_DIRECTION};

    private CompactObject() {
    }

    /** The object's numbers in {@link #NUMBERS}' order, NaN where the server sent none. */
    static void numbers(SeenObject object, double[] into) {
        into[0] = object.distance();
        into[1] = object.direction();
        into[2] = object.distanceChange();
        into[3] = object.directionChange();
        into[4] = object.bodyFacing();
        into[5] = object.headFacing();
        into[6] = object.pointingDirection();
    }

    /**
     * The kind a short name stands for, by its first letter in either case ({@code b}, {@code g},
     * {@code f}, {@code l}, {@code p}), as the protocol names objects; null for any other name.
     */
    static ObjectKind kindOf(String name) {
        if (name.isEmpty()) {
            return null;
        }
        return switch (Character.toLowerCase(name.charAt(0))) {
            case 'b' -> ObjectKind.BALL;
            case 'g' -> ObjectKind.GOAL;
            case 'f' -> ObjectKind.FLAG;
            case 'l' -> ObjectKind.LINE;
            case 'p' -> ObjectKind.PLAYER;
            default -> null;
        };
    }
}
