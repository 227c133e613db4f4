package org.scenes.agent.imitation;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.ActionType;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;

/**
 * How a recorded player took its team's set plays: for each kind (kick-off, free kick, kick-in,
 * corner, goal kick), the kicks that ended them and how many cycles after the play mode began
 * each came. A team such as HELIOS base waits at a set play (for its players to take their
 * places) and then kicks; the wait depends on time, which no scene feature holds, so an
 * imitator that stands at the ball matches the waiting scenes for ever. The imitator takes the
 * recorded kick once it has waited as long as its counterpart did (the median wait), and kicks
 * as recorded when its matching chooses to kick sooner: the teacher's restarts (HELIOS base's
 * kick-offs: a pass back towards its defenders) are in too few scenes for a nearest neighbour to
 * aim them.
 */
final class SetPlayKicks {
    /** The kick-off's kind: its play mode without the side letter. */
    static final String KICK_OFF = "kick_off";
    /** Play modes, without their side letter, that the side named in them restarts with a kick. */
    private static final List<String> KINDS = List.of(KICK_OFF, "free_kick", "indirect_free_kick", "kick_in",
            "corner_kick", "goal_kick");

    /** One recorded set-play kick: the scene that holds it, and its wait. */
    record Kick(Scene scene, int waited) {
    }

    static final SetPlayKicks NONE = new SetPlayKicks(Map.of());

    private final Map<String, List<Kick>> byKind;

    private SetPlayKicks(Map<String, List<Kick>> byKind) {
        this.byKind = byKind;
    }

    /** The set-play kicks of one recorded player's scenes, in cycle order. */
    static SetPlayKicks of(Iterable<Scene> scenes) {
        Map<String, List<Kick>> byKind = new HashMap<>();
        String mode = "";
        int since = 0;
        boolean kicked = false;
        for (Scene scene : scenes) {
            World world = scene.world();
            if (world == null || scene.observer() == null) {
                continue;
            }
            if (!world.playMode().equals(mode)) {
                // the kick that ended a set play may carry the next play mode already: its world
                // model heard the referee's play_on of the same cycle (so HELIOS base's kick-offs)
                String ended = ownKind(mode, scene.observer().side());
                if (ended != null && !kicked && scene.actionType() == ActionType.KICK) {
                    byKind.computeIfAbsent(ended, k -> new ArrayList<>()).add(new Kick(scene, scene.cycle() - since));
                }
                mode = world.playMode();
                since = scene.cycle();
                kicked = false;
            }
            String kind = ownKind(mode, scene.observer().side());
            if (kind != null && !kicked && scene.actionType() == ActionType.KICK) {
                kicked = true;
                byKind.computeIfAbsent(kind, k -> new ArrayList<>()).add(new Kick(scene, scene.cycle() - since));
            }
        }
        return byKind.isEmpty() ? NONE : new SetPlayKicks(byKind);
    }

    /** The same, merged: the kicks of several files of one player. */
    SetPlayKicks with(SetPlayKicks more) {
        if (more.byKind.isEmpty()) {
            return this;
        }
        Map<String, List<Kick>> merged = new HashMap<>();
        byKind.forEach((kind, kicks) -> merged.computeIfAbsent(kind, k -> new ArrayList<>()).addAll(kicks));
        more.byKind.forEach((kind, kicks) -> merged.computeIfAbsent(kind, k -> new ArrayList<>()).addAll(kicks));
        return new SetPlayKicks(merged);
    }

    /**
     * These kicks, and for the kinds this player never took, {@code team}'s: a player that stands
     * at the ball of a set play its counterpart never took (the ball came to it, or its
     * knowledge sent it there) takes it as its team did, rather than waiting at the ball for ever.
     */
    SetPlayKicks orTeams(SetPlayKicks team) {
        if (team.byKind.keySet().stream().allMatch(byKind::containsKey)) {
            return this;
        }
        Map<String, List<Kick>> merged = new HashMap<>(team.byKind);
        merged.putAll(byKind);
        return new SetPlayKicks(merged);
    }

    /**
     * The kick to take now: in a set play of the player's own team that has lasted {@code waited}
     * cycles, at least the median of the recorded waits of that kind, the recorded kick of that kind
     * {@link #taken nearest to where the ball lies}; null before, in other play modes, or when the
     * player never took one of that kind.
     */
    Scene due(String mode, Side side, int waited, double ballX, double ballY) {
        List<Kick> kicks = kicks(mode, side);
        if (kicks == null) {
            return null;
        }
        return waited >= medianWait(kicks) ? nearest(kicks, ballX, ballY) : null;
    }

    /**
     * The recorded kick of this set play's kind (own side) taken with the ball nearest to
     * ({@code ballX}, {@code ballY}) in the player's own frame (the first recorded when the ball's
     * place is unknown): a kick-in from the other touchline or a corner from the other flag would
     * send the ball out of the field. Null in other play modes or for a kind never taken.
     */
    Scene taken(String mode, Side side, double ballX, double ballY) {
        List<Kick> kicks = kicks(mode, side);
        return kicks == null ? null : nearest(kicks, ballX, ballY);
    }

    /** The recorded kicks of this set play's kind when the player's own side restarts it, else null. */
    private List<Kick> kicks(String mode, Side side) {
        String kind = ownKind(mode, side);
        return kind == null ? null : byKind.get(kind);
    }

    private static Scene nearest(List<Kick> kicks, double ballX, double ballY) {
        Scene nearest = kicks.get(0).scene();
        double least = Double.POSITIVE_INFINITY;
        for (Kick kick : kicks) {
            World world = kick.scene().world();
            double distance = Math.hypot(world.ballX() - ballX, world.ballY() - ballY);
            if (distance < least) {
                least = distance;
                nearest = kick.scene();
            }
        }
        return nearest;
    }

    /** Whether the recorded player took at least one set play of this kind ({@code kick_off}, ...). */
    boolean took(String kind) {
        return byKind.containsKey(kind);
    }

    /** The median of the recorded waits before kicks of this kind, or -1 when none was taken. */
    int medianWait(String kind) {
        List<Kick> kicks = byKind.get(kind);
        return kicks == null ? -1 : medianWait(kicks);
    }

    private static int medianWait(List<Kick> kicks) {
        return kicks.stream().mapToInt(Kick::waited).sorted().toArray()[kicks.size() / 2];
    }

    /** Total recorded set-play kicks, for tests and reports. */
    int size() {
        return byKind.values().stream().mapToInt(List::size).sum();
    }

    /** The set-play kind of a play mode when the player's own side restarts it ({@code kick_off_l} for a left player), else null. */
    static String ownKind(String mode, Side side) {
        if (side == null || mode.length() < 3 || mode.charAt(mode.length() - 2) != '_'
                || mode.charAt(mode.length() - 1) != side.letter()) {
            return null;
        }
        String kind = mode.substring(0, mode.length() - 2);
        return KINDS.contains(kind) ? kind : null;
    }
}
