package org.scenes.internal.scene;

import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;

/** How a seen object relates to the player that saw it: the one rule conversion and scene files share. */
public final class Relations {
    private Relations() {
    }

    /**
     * Goals are own or opponent by the observer's side ({@code g r} is own for the right side);
     * players are teammates when their team is the observer's, opponents when another team is
     * readable, unknown otherwise; objects sensed behind (upper case) carry no identity; the ball,
     * flags and lines relate to no one.
     *
     * @param kind the object's kind
     * @param name its short name, upper case when sensed behind
     * @param team a player's team, empty when not readable
     * @param observer the player that saw it
     * @return the relation
     */
    public static Relation of(ObjectKind kind, String name, String team, Observer observer) {
        if (kind == ObjectKind.GOAL) {
            if (Character.isUpperCase(name.charAt(0)) || name.length() < 3 || observer.side() == null) {
                return Relation.UNKNOWN;
            }
            return name.charAt(2) == observer.side().letter() ? Relation.OWN : Relation.OPPONENT;
        }
        if (kind == ObjectKind.PLAYER) {
            if (team.isEmpty() || observer.team().isEmpty()) {
                return Relation.UNKNOWN;
            }
            return team.equals(observer.team()) ? Relation.TEAMMATE : Relation.OPPONENT;
        }
        return Relation.NONE;
    }
}
