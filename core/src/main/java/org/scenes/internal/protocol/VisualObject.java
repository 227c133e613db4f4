package org.scenes.internal.protocol;

import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.SeenObject;

/**
 * One object of a {@code see} message as the server described it. Long names from old protocol
 * versions are normalised to the short form ({@code (flag c t)} becomes {@code f c t}); objects
 * sensed behind the player keep their upper-case name ({@code B}, {@code F}, {@code G}, {@code P}).
 * Numbers the server did not send are {@code NaN}. A scene holds it as a {@link SeenObject},
 * made by {@link #seen}: the same thirteen components plus what only the observer knows.
 *
 * @param kind ball, goal, flag, line or player
 * @param name short name without player details: {@code b}, {@code g r}, {@code f p r b}, {@code p}
 * @param team a player's team, empty when not readable
 * @param uniformNumber a player's uniform number, 0 when not readable
 * @param goalie whether the player carries the goalie mark
 * @param mark {@code 't'} tackling, {@code 'k'} kicked, {@code ' '} none
 */
public record VisualObject(ObjectKind kind, String name, String team, int uniformNumber, boolean goalie,
                           double distance, double direction, double distanceChange, double directionChange,
                           double bodyFacing, double headFacing, double pointingDirection, char mark) {

    /** Whether the server reported this object in upper case (behind the player, no identity). */
    public boolean behind() {
        return Character.isUpperCase(name.charAt(0));
    }

    /**
     * This object as a scene holds it, the one step from what the server said to a {@link SeenObject}:
     * every component kept, plus the relation to the observer (which needs its side and team) and the
     * cell of {@code grid}.
     */
    public SeenObject seen(Relation relation, Grid grid) {
        return new SeenObject(kind, name, team, uniformNumber, goalie, relation, distance, direction, distanceChange,
                directionChange, bodyFacing, headFacing, pointingDirection, mark, grid.cell(distance, direction));
    }
}
