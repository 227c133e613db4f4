package org.scenes.agent.imitation;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Random;
import java.util.TreeMap;
import java.util.function.Function;
import java.util.function.Supplier;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.scene.SceneSource;
import org.scenes.internal.target.BallWatch;
import org.scenes.internal.target.Destinations;
import org.scenes.internal.target.Formation;
import org.scenes.internal.target.Replay;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/**
 * What an imitation team knows, by role: the whole team's scenes, and for each recorded player
 * (its uniform number, from the scene files' {@code source}) its own: its <em>counterpart</em>'s
 * scenes, its goalie flag and the kick-off moves it sent. The imitating player with uniform
 * number N plays on the knowledge of the recorded player N ({@link Knowledge#COUNTERPART}), or on
 * the team's when there is none or when asked ({@link Knowledge#TEAM}); either way it takes its
 * kick-off moves from its counterpart and inits as goalie when its counterpart was the goalie.
 */
public final class ImitationTeam {
    /** Whose scenes each imitating player matches against. */
    public enum Knowledge {
        /** Every player: the scenes of the whole team. */
        TEAM,
        /** Each player: the scenes of the recorded player with its uniform number, else the team's. */
        COUNTERPART;

        public String key() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** The knowledge with this key ({@code team}, {@code counterpart}), or null. */
        public static Knowledge fromKey(String key) {
            for (Knowledge knowledge : values()) {
                if (knowledge.key().equals(key)) {
                    return knowledge;
                }
            }
            return null;
        }
    }

    /**
     * One recorded player's role.
     *
     * @param recognizer the nearest scenes among its own, or null when the team's are used
     * @param moves the first {@code move} of each run of moves in its scenes, in order: where it
     *              placed itself before kick-offs (empty when its scenes hold none)
     * @param movedInPlay whether it placed itself again after time 0 (after goals, at half time);
     *                    the real Krislet client places itself once, at time 0
     * @param setPlayKicks the kicks with which it took its team's set plays, and after how long
     * @param placesOnce whether each of its placements was a single {@code move} (HELIOS base), not a
     *                   run of them repeated on every view until the kick-off (Krislet)
     */
    record Counterpart(int unum, boolean goalie, Recognizer recognizer, List<Action> moves, boolean movedInPlay,
                       SetPlayKicks setPlayKicks, boolean placesOnce) {
        Counterpart {
            moves = List.copyOf(moves);
        }
    }

    private final Recognizer team;
    private final Map<Integer, Counterpart> counterparts;
    private final Knowledge knowledge;
    /** Every recorded player's set-play kicks together. */
    private final SetPlayKicks teamSetPlayKicks;

    private ImitationTeam(Recognizer team, Map<Integer, Counterpart> counterparts, Knowledge knowledge) {
        this.team = Objects.requireNonNull(team, "team");
        this.counterparts = Collections.unmodifiableMap(new TreeMap<>(counterparts));
        this.knowledge = Objects.requireNonNull(knowledge, "knowledge");
        SetPlayKicks kicks = SetPlayKicks.NONE;
        for (Counterpart counterpart : this.counterparts.values()) {
            if (counterpart.setPlayKicks() != null) {
                kicks = kicks.with(counterpart.setPlayKicks());
            }
        }
        teamSetPlayKicks = kicks;
    }

    /** A team without roles: every player matches {@code recognizer}'s scenes, as one pool. */
    public static ImitationTeam of(Recognizer recognizer) {
        return new ImitationTeam(recognizer, Map.of(), Knowledge.TEAM);
    }

    /**
     * Reads the scene files: the team's knowledge base of all of them and, by the uniform number
     * in each file's {@code source}, one per recorded player (counterpart knowledge only); files
     * with no uniform number (merged ones) count for the team only.
     *
     * @param recognizers makes the recognizer (metric, k) of a knowledge base
     */
    public static ImitationTeam load(List<Path> files, Supplier<List<SceneTransform>> transforms,
                                     Function<KnowledgeBase, Recognizer> recognizers, Knowledge knowledge) {
        Map<Integer, List<Path>> byUnum = new TreeMap<>();
        Map<Integer, Boolean> goalies = new TreeMap<>();
        Map<Integer, List<Action>> moves = new TreeMap<>();
        Map<Integer, Boolean> movedInPlay = new TreeMap<>();
        Map<Integer, SetPlayKicks> setPlayKicks = new TreeMap<>();
        Map<Integer, Boolean> placesOnce = new TreeMap<>();
        for (Path file : files) {
            try (SceneFileReader reader = SceneFileReader.open(file)) {
                SceneSource source = reader.header().source();
                int unum = source.observer().uniformNumber();
                if (unum > 0) {
                    byUnum.computeIfAbsent(unum, u -> new ArrayList<>()).add(file);
                    goalies.merge(unum, source.goalie(), Boolean::logicalOr);
                    // the recorded moves and kicks, before any transform (a mirror would add moves never sent)
                    List<Scene> recorded = new ArrayList<>();
                    reader.forEachRemaining(recorded::add);
                    List<Action> placements = kickOffMoves(recorded);
                    moves.computeIfAbsent(unum, u -> new ArrayList<>()).addAll(placements);
                    movedInPlay.merge(unum, recorded.stream().anyMatch(
                            scene -> scene.cycle() > 0 && scene.actionType() == ActionType.MOVE), Boolean::logicalOr);
                    setPlayKicks.merge(unum, SetPlayKicks.of(recorded), SetPlayKicks::with);
                    long moveScenes = recorded.stream().filter(scene -> scene.actionType() == ActionType.MOVE).count();
                    placesOnce.merge(unum, moveScenes == placements.size(), Boolean::logicalAnd);
                }
            }
        }
        boolean anyMovedInPlay = movedInPlay.isEmpty() || movedInPlay.containsValue(true);
        Recognizer team = recognizers.apply(placements(KnowledgeBase.load(files, transforms), anyMovedInPlay));
        Map<Integer, Counterpart> counterparts = new TreeMap<>();
        for (Map.Entry<Integer, List<Path>> entry : byUnum.entrySet()) {
            int unum = entry.getKey();
            Recognizer recognizer = knowledge == Knowledge.COUNTERPART
                    ? recognizers.apply(placements(KnowledgeBase.load(entry.getValue(), transforms),
                            movedInPlay.get(unum))) : null;
            counterparts.put(unum, new Counterpart(unum, goalies.get(unum), recognizer, moves.get(unum),
                    movedInPlay.get(unum), setPlayKicks.get(unum), placesOnce.get(unum)));
        }
        return new ImitationTeam(team, counterparts, knowledge);
    }

    /**
     * The knowledge to match in: without its placements before the kick-off when the recorded
     * player never placed itself again. The brain places itself from the counterpart's recorded
     * moves; matched in play, such a scene made a player send {@code move}s that the server ignores
     * (the real Krislet client places itself once, at time 0).
     */
    private static KnowledgeBase placements(KnowledgeBase knowledge, boolean movedInPlay) {
        return movedInPlay ? knowledge : knowledge.without(scene -> scene.actionType() == ActionType.MOVE);
    }

    /**
     * This team with more scenes: DAgger's labelled sequences, by the uniform number of the player
     * that built them. All join the team's knowledge; each player's also join its counterpart's
     * (when it has its own). Moves, set-play kicks and goalies stay as recorded.
     *
     * @param recognizers makes the recognizer (metric, k) of a knowledge base
     */
    public ImitationTeam plus(Map<Integer, List<List<Scene>>> sequences, Supplier<List<SceneTransform>> transforms,
                              Function<KnowledgeBase, Recognizer> recognizers) {
        List<List<Scene>> all = sequences.values().stream().flatMap(List::stream).toList();
        Map<Integer, Counterpart> corrected = new TreeMap<>();
        for (Counterpart counterpart : counterparts.values()) {
            List<List<Scene>> own = sequences.getOrDefault(counterpart.unum(), List.of());
            Recognizer recognizer = counterpart.recognizer() == null || own.isEmpty() ? counterpart.recognizer()
                    : recognizers.apply(counterpart.recognizer().knowledge().plus(own, transforms));
            corrected.put(counterpart.unum(), new Counterpart(counterpart.unum(), counterpart.goalie(), recognizer,
                    counterpart.moves(), counterpart.movedInPlay(), counterpart.setPlayKicks(), counterpart.placesOnce()));
        }
        return new ImitationTeam(recognizers.apply(team.knowledge().plus(all, transforms)), corrected, knowledge);
    }

    /** The first move of each run of scenes whose primary action is a move. */
    static List<Action> kickOffMoves(Iterable<Scene> scenes) {
        List<Action> moves = new ArrayList<>();
        boolean inRun = false;
        for (Scene scene : scenes) {
            boolean move = scene.actionType() == ActionType.MOVE;
            if (move && !inRun) {
                moves.add(scene.primaryAction());
            }
            inRun = move;
        }
        return moves;
    }

    /** Brains for the players, each finding its counterpart by the uniform number the server gives it. */
    public BrainFactory brains(Supplier<ActionSelector> selectors, Supplier<List<SceneTransform>> transforms,
                               ImitationBrain.Guards guards) {
        return brains(selectors, transforms, guards, Replay.RAW);
    }

    private static void prepare(KnowledgeBase knowledge) {
        Destinations.of(knowledge);
        BallWatch.of(knowledge);
        Formation.of(knowledge);
    }

    /** The same, each brain carrying out its chosen actions as {@code replay} says. */
    public BrainFactory brains(Supplier<ActionSelector> selectors, Supplier<List<SceneTransform>> transforms,
                               ImitationBrain.Guards guards, Replay replay) {
        if (replay == Replay.TARGET) {
            // every role's destinations, ball watch and formation now: made when a player's init arrived, they
            // held up a real-time team's init answers, and its first cycles' commands left late
            prepare(team.knowledge());
            counterparts.values().stream().filter(counterpart -> counterpart.recognizer() != null)
                    .forEach(counterpart -> prepare(counterpart.recognizer().knowledge()));
        }
        return new BrainFactory() {
            @Override
            public Brain create(String teamName, Random random) {
                return new ImitationBrain(teamName, ImitationTeam.this, selectors.get(), transforms, random, guards,
                        replay);
            }

            @Override
            public boolean goalie(int unum) {
                Counterpart counterpart = counterparts.get(unum);
                return counterpart != null && counterpart.goalie();
            }
        };
    }

    /** The team's recognizer, for players before their number is known and those without a counterpart. */
    Recognizer team() {
        return team;
    }

    /**
     * The set-play kicks player {@code unum} takes: its counterpart's, and the team's for the kinds
     * its counterpart never took ({@link SetPlayKicks#orTeams}).
     */
    SetPlayKicks setPlayKicks(int unum) {
        Counterpart counterpart = counterparts.get(unum);
        return counterpart == null || counterpart.setPlayKicks() == null ? teamSetPlayKicks
                : counterpart.setPlayKicks().orTeams(teamSetPlayKicks);
    }

    /**
     * How many cycles player {@code unum} leaves its team's kick-offs to a teammate, 0 when it may
     * take them at once. The kick-off ball lies on the centre spot, and a team such as HELIOS base
     * has one player take every kick-off (its number 11) while the others hold their places;
     * imitators that each took their world model's word for being the nearest ran to the ball
     * together, and two kicking in one step sent it 40 m back to their own goal. So a player whose
     * counterpart took none, in a team whose recorded players took some, waits twice as long as
     * the team waited before its kick-offs: long enough for the taker, not for ever when the
     * taker is not on the pitch.
     */
    int kickOffWait(int unum) {
        Counterpart counterpart = counterparts.get(unum);
        int teamWait = teamSetPlayKicks.medianWait(SetPlayKicks.KICK_OFF);
        if (teamWait < 0 || counterpart != null && counterpart.setPlayKicks() != null
                && counterpart.setPlayKicks().took(SetPlayKicks.KICK_OFF)) {
            return 0;
        }
        return 2 * teamWait;
    }

    /** The recorded player with this uniform number, or null. */
    Counterpart counterpart(int unum) {
        return counterparts.get(unum);
    }

    /** What player {@code unum} matches against: its counterpart's scenes when asked and recorded, else the team's. */
    Recognizer recognizer(int unum) {
        Counterpart counterpart = counterparts.get(unum);
        return counterpart != null && counterpart.recognizer() != null ? counterpart.recognizer() : team;
    }

    /** The team's knowledge base: every player's scenes. */
    public KnowledgeBase knowledge() {
        return team.knowledge();
    }

    /** Scenes in the team's knowledge base. */
    public int scenes() {
        return team.knowledge().size();
    }

    /** E.g. "counterpart knowledge for 11 players (goalie 1)", for the user. */
    public String describe() {
        if (counterparts.isEmpty()) {
            return "team knowledge (no uniform numbers in the files)";
        }
        List<Integer> goalies = counterparts.values().stream().filter(Counterpart::goalie).map(Counterpart::unum).toList();
        return knowledge.key() + " knowledge, " + counterparts.size() + " recorded players"
                + (goalies.isEmpty() ? "" : " (goalie " + goalies.get(0) + ")");
    }
}
