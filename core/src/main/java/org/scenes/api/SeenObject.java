package org.scenes.api;

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
 * @param confidence 1 for an object the server reported in this {@code see}; below 1 (and above 0)
 *                   for one a transform remembered from earlier scenes, falling with its age. Never
 *                   written to scene files: transforms rebuild remembered objects when scenes are read.
 */
public record SeenObject(ObjectKind kind, String name, String team, int uniformNumber, boolean goalie,
                         Relation relation, double distance, double direction,
                         double distanceChange, double directionChange,
                         double bodyFacing, double headFacing, double pointingDirection,
                         char mark, Cell cell, double confidence) {

    public static final char NO_MARK = ' ';

    /** An object the server reported in this {@code see} (confidence 1). */
    public SeenObject(ObjectKind kind, String name, String team, int uniformNumber, boolean goalie,
                      Relation relation, double distance, double direction,
                      double distanceChange, double directionChange,
                      double bodyFacing, double headFacing, double pointingDirection,
                      char mark, Cell cell) {
        this(kind, name, team, uniformNumber, goalie, relation, distance, direction, distanceChange, directionChange,
                bodyFacing, headFacing, pointingDirection, mark, cell, 1);
    }

    public SeenObject {
        if (!(confidence > 0 && confidence <= 1)) {
            throw new IllegalArgumentException("an object's confidence lies in (0, 1], not " + confidence);
        }
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
                distanceChange, directionChange, bodyFacing, headFacing, pointingDirection, mark, newCell, confidence);
    }

    /** Whether a transform carried this object from earlier scenes rather than the server reporting it now. */
    public boolean remembered() {
        return confidence < 1;
    }

    /**
     * The same object remembered at another place with the given confidence (below 1), its cell
     * taken from {@code grid}; the changes the server reported are kept, for further extrapolation.
     */
    public SeenObject remembered(double newDistance, double newDirection, double newConfidence, Grid grid) {
        if (!(newConfidence < 1)) {
            throw new IllegalArgumentException("a remembered object's confidence is below 1, not " + newConfidence);
        }
        return new SeenObject(kind, name, team, uniformNumber, goalie, relation, newDistance, newDirection,
                distanceChange, directionChange, bodyFacing, headFacing, pointingDirection, mark,
                grid.cell(newDistance, newDirection), newConfidence);
    }

    /**
     * What names this object across scenes: kind, name, relation, and a player's team and
     * uniform number. Objects sensed behind (upper-case names) and players without a readable
     * number have no identity of their own; for them this says only what they are.
     */
    public String identity() {
        return kind.key() + '|' + name + '|' + relation.key() + '|' + team + '|' + uniformNumber;
    }
}
