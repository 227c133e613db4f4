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

    /** The {@link #mark} of an object the server gave no mark (neither tackling nor kicked). */
    public static final char NO_MARK = ' ';

    /**
     * An object the server reported in this {@code see} (confidence 1).
     *
     * @param kind ball, goal, flag, line or player
     * @param name the server's short name, upper case when sensed behind
     * @param team player's team, empty or null when not readable
     * @param uniformNumber player's uniform number, 0 when not readable
     * @param goalie whether the player carries the goalie mark
     * @param relation relation to the observer
     * @param distance distance in metres
     * @param direction direction in degrees relative to the observer's head, positive to the right
     * @param distanceChange distance change per cycle, in metres
     * @param directionChange direction change per cycle, in degrees
     * @param bodyFacing a player's body direction relative to the observer's head, in degrees
     * @param headFacing a player's head direction relative to the observer's head, in degrees
     * @param pointingDirection the direction a player points to, in degrees
     * @param mark {@code 't'}, {@code 'k'} or {@link #NO_MARK}
     * @param cell the object's cell in the scene's grid
     */
    public SeenObject(ObjectKind kind, String name, String team, int uniformNumber, boolean goalie,
                      Relation relation, double distance, double direction,
                      double distanceChange, double directionChange,
                      double bodyFacing, double headFacing, double pointingDirection,
                      char mark, Cell cell) {
        this(kind, name, team, uniformNumber, goalie, relation, distance, direction, distanceChange, directionChange,
                bodyFacing, headFacing, pointingDirection, mark, cell, 1);
    }

    /**
     * Checks the components: confidence in (0, 1], kind, name, relation and cell given, a known mark.
     *
     * @param kind ball, goal, flag, line or player
     * @param name the server's short name, upper case when sensed behind
     * @param team player's team, empty or null when not readable
     * @param uniformNumber player's uniform number, 0 when not readable
     * @param goalie whether the player carries the goalie mark
     * @param relation relation to the observer
     * @param distance distance in metres
     * @param direction direction in degrees relative to the observer's head, positive to the right
     * @param distanceChange distance change per cycle, in metres
     * @param directionChange direction change per cycle, in degrees
     * @param bodyFacing a player's body direction relative to the observer's head, in degrees
     * @param headFacing a player's head direction relative to the observer's head, in degrees
     * @param pointingDirection the direction a player points to, in degrees
     * @param mark {@code 't'}, {@code 'k'} or {@link #NO_MARK}
     * @param cell the object's cell in the scene's grid
     * @param confidence 1 for an object reported now, in (0, 1) for a remembered one
     */
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

    /**
     * A landmark or ball seen with distance and direction only.
     *
     * @param kind what it is
     * @param name the server's short name, e.g. {@code b} or {@code f p r b}
     * @param relation relation to the observer ({@link Relation#NONE} for the ball and flags)
     * @param distance distance in metres
     * @param direction direction in degrees relative to the observer's head, positive to the right
     * @param grid the grid that gives the object's cell
     * @return the object, with confidence 1 and every other number {@code NaN}
     */
    public static SeenObject simple(ObjectKind kind, String name, Relation relation, double distance,
                                    double direction, Grid grid) {
        return new SeenObject(kind, name, "", 0, false, relation, distance, direction,
                Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, NO_MARK,
                grid.cell(distance, direction));
    }

    /**
     * Whether the server reported this object in upper case: sensed behind, without identity.
     *
     * @return true for an upper-case name
     */
    public boolean behind() {
        return Character.isUpperCase(name.charAt(0));
    }

    /**
     * The same object with another cell, e.g. after re-discretising with another grid.
     *
     * @param newCell the cell it takes
     * @return a copy that differs in its cell only
     */
    public SeenObject withCell(Cell newCell) {
        return new SeenObject(kind, name, team, uniformNumber, goalie, relation, distance, direction,
                distanceChange, directionChange, bodyFacing, headFacing, pointingDirection, mark, newCell, confidence);
    }

    /**
     * Whether a transform carried this object from earlier scenes rather than the server reporting it now.
     *
     * @return true when its confidence is below 1
     */
    public boolean remembered() {
        return confidence < 1;
    }

    /**
     * The same object remembered at another place with the given confidence (below 1), its cell
     * taken from {@code grid}; the changes the server reported are kept, for further extrapolation.
     *
     * @param newDistance where it is believed to be now: distance in metres
     * @param newDirection and direction in degrees relative to the observer's head
     * @param newConfidence how sure, above 0 and below 1
     * @param grid the grid that gives its new cell
     * @return the remembered copy
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
     *
     * @return the identity as one string, equal for the same object in two scenes
     */
    public String identity() {
        return kind.key() + '|' + name + '|' + relation.key() + '|' + team + '|' + uniformNumber;
    }
}
