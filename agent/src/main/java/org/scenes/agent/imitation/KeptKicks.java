package org.scenes.agent.imitation;

import static org.scenes.internal.vision.Landmarks.PITCH_HALF_LENGTH;

import java.util.ArrayList;
import java.util.List;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Neighbour;
import org.scenes.api.Scene;
import org.scenes.api.World;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.target.KickCourse;
import org.scenes.internal.target.KickCourse.Outcome;
import org.scenes.internal.target.Targets;

/**
 * Under target replay, the kicks of the {@link #NEIGHBOURS} nearest neighbours, each carried out
 * from the player's own state, stand in for a kick in play on that would lose the ball
 * ({@link KickCourse}): the first that scores, else the first that keeps it; and near the
 * opponent goal for a kick that does not score, the first that scores. The chosen kick stays
 * when none does better. The recorded kick went where its player's teammates stood, and its
 * player chose it by where its opponents stood; the imitator's stand elsewhere. Not thread-safe:
 * one per player.
 */
final class KeptKicks {
    /** Neighbours whose kicks are looked at: about as many kicks as a HELIOS base player's game holds near one moment. */
    static final int NEIGHBOURS = 20;
    /** Metres from the opponent goal's centre within which a kick may score: a kick at full speed rolls about 37 m in its course. */
    static final double SHOOTING_RANGE = 35;

    private long kept;
    private long shots;
    private long handedOver;

    /**
     * {@code actions} (body action first, as {@code query}'s player would send them), or the same
     * with the body's kick replaced by a neighbour's kick that does better.
     *
     * @param search the scene the recognizer searches with (the query after any transforms)
     */
    List<Action> choose(List<Action> actions, Scene query, Scene search, Recognizer recognizer) {
        World own = query.world();
        if (actions.isEmpty() || actions.get(0).type() != ActionType.KICK || own == null
                || !"play_on".equals(own.playMode())) {
            return actions;
        }
        Outcome chosen = KickCourse.outcome(actions.get(0), own);
        boolean inRange = own.ballKnown() && Math.hypot(PITCH_HALF_LENGTH - own.ballX(), own.ballY()) <= SHOOTING_RANGE;
        if (chosen == Outcome.SCORES || chosen == Outcome.UNKNOWN || chosen == Outcome.KEEPS && !inRange) {
            return actions;
        }
        Action keeping = null;
        for (Neighbour neighbour : recognizer.nearest(search, NEIGHBOURS)) {
            Action recorded = neighbour.scene().primaryAction();
            if (recorded == null || recorded.type() != ActionType.KICK) {
                continue;
            }
            Action kick = Targets.reach(List.of(recorded), neighbour.scene(), query).get(0);
            Outcome outcome = KickCourse.outcome(kick, own);
            if (outcome == Outcome.SCORES) {
                shots++;
                return replaced(actions, kick);
            }
            if (keeping == null && outcome == Outcome.KEEPS) {
                keeping = kick;
            }
        }
        if (chosen == Outcome.KEEPS) {
            return actions;
        }
        if (keeping == null) {
            handedOver++;
            return actions;
        }
        kept++;
        return replaced(actions, keeping);
    }

    private static List<Action> replaced(List<Action> actions, Action kick) {
        List<Action> instead = new ArrayList<>(actions);
        instead.set(0, kick);
        return List.copyOf(instead);
    }

    /** Kicks that would have lost the ball, replaced by one that keeps it. */
    long kept() {
        return kept;
    }

    /** Kicks replaced by one that scores. */
    long shots() {
        return shots;
    }

    /** Kicks sent though they lose the ball: no neighbour's kick did better. */
    long handedOver() {
        return handedOver;
    }
}
