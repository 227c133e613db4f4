package org.scenes.scene;

/**
 * One object of a {@code see} message, with everything the server said about it.
 * Numeric fields the server did not send are {@code NaN}.
 *
 * @param kind ball, goal, flag, line or player
 * @param name the server's short name without player details: {@code b}, {@code g r},
 *             {@code f p r b}, {@code l b}, {@code p}; upper case ({@code B}, {@code F}, {@code G},
 *             {@code P}) for objects sensed behind the player, which carry no identity
 * @param team player's team, empty when not readable
 * @param uniformNumber player's uniform number, 0 when not readable
 * @param goalie whether the player carries the goalie mark
 * @param relation relation to the observer (own/opponent goal, teammate/opponent/unknown player)
 * @param distance distance in metres
 * @param direction direction in degrees relative to the observer's head, positive to the right
 * @param distanceChange distance change per cycle
 * @param directionChange direction change per cycle
 * @param bodyFacing a player's body direction relative to the observer's head
 * @param headFacing a player's head direction relative to the observer's head
 * @param pointingDirection the direction a player points to
 * @param mark {@code 't'} (tackling) or {@code 'k'} (kicked), {@code ' '} when absent
 * @param cell the object's cell in the scene's grid
 */
public record SeenObject(ObjectKind kind, String name, String team, int uniformNumber, boolean goalie,
                         Relation relation, double distance, double direction,
                         double distanceChange, double directionChange,
                         double bodyFacing, double headFacing, double pointingDirection,
                         char mark, Cell cell) {

    public static final char NO_MARK = ' ';

    public SeenObject {
        if (kind == null || name == null || name.isEmpty() || relation == null || cell == null) {
            throw new IllegalArgumentException("a seen object needs kind, name, relation and cell");
        }
        team = team == null ? "" : team;
        if (mark != NO_MARK && mark != 't' && mark != 'k') {
            throw new IllegalArgumentException("object mark must be 't' or 'k', not '" + mark + "'");
        }
    }

    /** A landmark or ball seen with distance and direction only. */
    public static SeenObject simple(ObjectKind kind, String name, Relation relation, double distance,
                                    double direction, Grid grid) {
        return new SeenObject(kind, name, "", 0, false, relation, distance, direction,
                Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, NO_MARK,
                grid.cell(distance, direction));
    }

    /** Whether the server reported this object in upper case: sensed behind, without identity. */
    public boolean behind() {
        return Character.isUpperCase(name.charAt(0));
    }

    /** The same object with another cell, e.g. after re-discretising with another grid. */
    public SeenObject withCell(Cell newCell) {
        return new SeenObject(kind, name, team, uniformNumber, goalie, relation, distance, direction,
                distanceChange, directionChange, bodyFacing, headFacing, pointingDirection, mark, newCell);
    }
}
