package org.scenes.agent.imitation;

import java.util.ArrayDeque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Random;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.function.Supplier;
import java.util.random.RandomGenerator;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.SeenObject;
import org.scenes.api.World;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.Parameters;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.SenseBody;
import org.scenes.internal.protocol.ServerNotice;
import org.scenes.internal.protocol.ViewWidth;
import org.scenes.internal.target.BallWatch;
import org.scenes.internal.target.Destinations;
import org.scenes.internal.target.Formation;
import org.scenes.internal.target.KickFollower;
import org.scenes.internal.target.Replay;
import org.scenes.internal.target.Steering;
import org.scenes.internal.target.Targets;
import org.scenes.internal.validate.Validator;
import org.scenes.internal.world.ServerDefaults;
import org.scenes.internal.world.WorldModel;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/**
 * The imitating player: every {@code see} becomes a scene exactly as the converter makes one
 * from a log ({@link SceneConverter#seenObjects}, the knowledge base's grid, the same
 * transforms), the recognizer finds the nearest stored scenes and the selector picks the action,
 * which is sent as its command; a chosen scene without action (a see its teacher left
 * unanswered) sends nothing. Before kick-off it moves to a random spot of its own half: the
 * recorded moves come before the first see, so no scene holds one.
 *
 * <p>Roles ({@link ImitationTeam}): once the server gives it its uniform number, the brain plays
 * on its counterpart's knowledge (or the team's). Its first move, and every move the selector
 * chooses from another player's scene, is its counterpart's recorded kick-off move, so the players
 * do not all go to one spot; the runtime sends the kick-off move again after goals only when the
 * counterpart's scenes hold moves (the teacher moved during the game).
 *
 * <p>Transforms such as {@code memory} remember earlier scenes with the action taken in them.
 * In validation that is the recorded action; here it is the action this brain chose, which is
 * known only after the query: so each decision runs fresh transforms over the last
 * {@link #HISTORY} scenes, each with its chosen action, and then over the new scene.
 *
 * <p>With {@link Guards} on, two of the thesis' remedies overrule the selector: a kick with the
 * ball out of reach (not seen within {@code player_size + ball_size + kickable_margin} of the
 * server's parameters) becomes the action of the nearest neighbour that is not a kick; and when
 * the same action has left what the player sees exactly unchanged for
 * {@link Guards#stuckSees()} sees in a row, the nearest neighbour with another action is taken.
 * Each firing is counted ({@link #counters()}).
 *
 * <p>Under target replay a choice that sends no body command (a stored scene where the teacher
 * only turned its neck, or a kick-off placement matched in play) gives way to the nearest of the
 * {@link #LOOK_FURTHER} neighbours that sends one ({@link #lookFurther}): at k 1, a player that
 * stood still saw the same again and stood there for the rest of the game.
 *
 * <p>Under target replay the player also keeps its ball as fresh as its teacher did
 * ({@link BallWatch}): a ball older than the teacher's usual turns the head to it, and one behind
 * the head's reach widens the view until it is seen again; with no ball known the body turns to
 * look for one ({@link BallWatch#search}).
 *
 * <p>Under target replay a kick in play on that would lose the ball (to an opponent the player
 * knows of, or over the line), or near the opponent goal one that would not score, gives way to a
 * further neighbour's kick that scores or keeps it ({@link KeptKicks}); after its kick an outfield
 * player runs after the ball while it can contest it ({@link KickFollower}); and an outfield player
 * that does not go for the ball and stands far from where its counterpart stood for that place of
 * the ball runs there ({@link Formation}).
 *
 * <p>A knowledge base of a player that acted every cycle (scenes of several see ages, e.g. a
 * librcsc team on synchronous vision) is played per cycle in synchronous mode: at each
 * {@code (think)} the latest view, with its age, is matched, and the chosen scene's body action
 * and its neck action are sent, as {@code validate} predicts them ({@link Validator#withNeck}).
 */
public final class ImitationBrain implements Brain {
    /** Scenes replayed through the transforms before each query; enough for one-step memory and more. */
    static final int HISTORY = 8;
    /**
     * How many neighbours a player under target replay looks through when its k nearest hold no
     * body command (k 1 and a stored scene where the teacher only turned its neck, or a kick-off
     * placement matched in play): standing still is no target to reach, and a player that stands
     * still sees the same again, so it would stand there for good.
     */
    static final int LOOK_FURTHER = 10;

    private final String team;
    private final ImitationTeam roles;
    /** The team's knowledge until the init answer, then the player's own (its counterpart's or the team's). */
    private Recognizer recognizer;
    /** where the recognizer's scenes' players ran; taken once per role, null unless replaying targets */
    private Destinations destinations;
    /** how old the teacher let its ball grow before looking at it; taken once per role, null unless replaying targets */
    private BallWatch ballWatch;
    /** the view the server last reported; the one to return to once a ball looked for behind is seen; a change to send */
    private ViewWidth view;
    private ViewWidth widenedFrom;
    private ViewWidth viewChange;
    /** what this player's previous decisions chose: a chase, a turn (not undone at once) */
    private final Steering steering = new Steering();
    /** the player's kicks in play on: one that would lose the ball gives way to one that keeps it or scores */
    private final KeptKicks keptKicks = new KeptKicks();
    /** the player's own kicks in play on: it goes after the ball while it can contest it */
    private final KickFollower kickFollower = new KickFollower();
    /** where the counterpart stood for each place of the ball; taken once per role, null unless replaying targets */
    private Formation formation;
    /** whether the counterpart was the goalie (it does not leave its area after its kicks) */
    private boolean goalie;
    /** how the counterpart took its team's set plays */
    private SetPlayKicks setPlayKicks = SetPlayKicks.NONE;
    /** cycles this player leaves its team's kick-offs to the teammate that takes them (ImitationTeam#kickOffWait) */
    private int kickOffWait;
    /** the play mode of the latest decision, and the cycle it began */
    private String playMode = "";
    private int playModeSince;
    /** play modes begun so far (several may begin in one cycle: goal, then kick-off), and the one of the last matched move */
    private int playModes;
    private int movedInMode = -1;
    /** whether the counterpart placed itself with a single move each time (then so does this player) */
    private boolean placesOnce;
    /** The counterpart's recorded kick-off moves: empty without a counterpart or moves. */
    private List<Action> counterpartMoves = List.of();
    private boolean counterpartMovedInPlay;
    /** Whether the brain was made with roles; without them it places itself and moves as it always did. */
    private final boolean withRoles;
    private final ActionSelector selector;
    private final Supplier<List<SceneTransform>> transforms;
    private final ArrayDeque<Scene> history = new ArrayDeque<>(HISTORY);
    private final Random random;
    private final MessageParser parser = new MessageParser();
    /** What the player believes of the game, built as scene conversion builds it; each query carries it. */
    private final WorldModel world;
    private Observer observer = Observer.UNKNOWN;
    private boolean placed;
    private final Guards guards;
    private final Replay replay;
    private double kickable = DEFAULT_KICKABLE;
    /**
     * Per-cycle play, for knowledge bases of players that act every cycle (several see ages): in
     * synchronous mode the decision is made at each {@code (think)} from the latest see and its age.
     */
    private boolean perCycle;
    private boolean synchronous;
    private See latestSee;
    /** Cycles (sense_body messages) since the latest see arrived. */
    private int stepsSinceSee;
    private long decisions;
    private long silent;
    /** decisions whose k nearest held no body command, taken from the {@link #LOOK_FURTHER} nearest instead */
    private long lookedFurther;
    private long kickGuarded;
    /** decisions that looked for a ball the world model did not know ({@link BallWatch#search}) */
    private long ballSearches;
    private long stuckGuarded;
    private Action lastAction;
    private List<SeenObject> lastSeen;
    private int unchanged;
    private Consumer<Scene> decided = scene -> { };

    /** Kickable distance of the default server: player_size 0.3 + ball_size 0.085 + kickable_margin 0.7. */
    static final double DEFAULT_KICKABLE = ServerDefaults.KICKABLE_AREA;

    /**
     * The loop guards.
     *
     * @param enabled whether they overrule the selector at all
     * @param stuckSees how many sees in a row an action may leave the view unchanged before another is taken
     */
    public record Guards(boolean enabled, int stuckSees) {
        /** Pure imitation: the selector's choice always stands. */
        public static final Guards OFF = new Guards(false, 0);
        /** Both guards, stuck after 5 unchanged sees (half a second of normal vision). */
        public static final Guards ON = new Guards(true, 5);

        public Guards {
            if (enabled && stuckSees < 2) {
                throw new IllegalArgumentException("the stuck guard needs at least 2 sees, not " + stuckSees);
            }
        }
    }

    /**
     * @param transforms makes a fresh chain of the scene transforms the knowledge base was built
     *                   with
     */
    public ImitationBrain(String team, Recognizer recognizer, ActionSelector selector,
                          Supplier<List<SceneTransform>> transforms, Random random) {
        this(team, recognizer, selector, transforms, random, Guards.OFF);
    }

    public ImitationBrain(String team, Recognizer recognizer, ActionSelector selector,
                          Supplier<List<SceneTransform>> transforms, Random random, Guards guards) {
        this(team, recognizer, selector, transforms, random, guards, Replay.RAW);
    }

    /** The same, carrying out the chosen scene's actions as {@code replay} says. */
    public ImitationBrain(String team, Recognizer recognizer, ActionSelector selector,
                          Supplier<List<SceneTransform>> transforms, Random random, Guards guards, Replay replay) {
        this(team, ImitationTeam.of(Objects.requireNonNull(recognizer, "recognizer")), selector, transforms, random,
                guards, false, replay);
    }

    /**
     * A player of an imitation team: its knowledge and kick-off moves are its counterpart's; it
     * carries out the chosen scene's actions as {@code replay} says.
     */
    public ImitationBrain(String team, ImitationTeam roles, ActionSelector selector,
                          Supplier<List<SceneTransform>> transforms, Random random, Guards guards, Replay replay) {
        this(team, roles, selector, transforms, random, guards, true, replay);
    }

    private ImitationBrain(String team, ImitationTeam roles, ActionSelector selector,
                           Supplier<List<SceneTransform>> transforms, Random random, Guards guards, boolean withRoles,
                           Replay replay) {
        this.replay = Objects.requireNonNull(replay, "replay");
        this.guards = Objects.requireNonNull(guards, "guards");
        this.team = Objects.requireNonNull(team, "team");
        this.world = new WorldModel(team);
        this.roles = Objects.requireNonNull(roles, "roles");
        this.withRoles = withRoles;
        this.recognizer = roles.team();
        // with roles, the role's own recognizer arrives with the init reply (takeRole)
        this.destinations = withRoles ? null : destinationsOf(recognizer);
        this.ballWatch = withRoles ? null : ballWatchOf(recognizer);
        this.selector = Objects.requireNonNull(selector, "selector");
        this.transforms = Objects.requireNonNull(transforms, "transforms");
        this.random = Objects.requireNonNull(random, "random");
        this.perCycle = recognizer.splitsBySeeAge();
    }

    /** A factory sharing one recognizer (it is thread-safe) with a fresh selector and transforms per player. */
    public static BrainFactory factory(Recognizer recognizer, Supplier<ActionSelector> selectors,
                                       Supplier<List<SceneTransform>> transforms) {
        return factory(recognizer, selectors, transforms, Guards.OFF);
    }

    /** The same, every brain with the given guards. */
    public static BrainFactory factory(Recognizer recognizer, Supplier<ActionSelector> selectors,
                                       Supplier<List<SceneTransform>> transforms, Guards guards) {
        return factory(recognizer, selectors, transforms, guards, Replay.RAW);
    }

    /** The same, every brain carrying out its chosen actions as {@code replay} says. */
    public static BrainFactory factory(Recognizer recognizer, Supplier<ActionSelector> selectors,
                                       Supplier<List<SceneTransform>> transforms, Guards guards, Replay replay) {
        return (team, random) -> new ImitationBrain(team, recognizer, selectors.get(), transforms, random, guards,
                replay);
    }

    @Override
    public void receive(String text, Consumer<String> send) {
        Message message = parser.parse(text);
        world.accept(message);
        if (message instanceof InitReply reply && reply.side() != null) {
            observer = new Observer(team, reply.side(), reply.uniformNumber());
            if (withRoles) {
                takeRole(reply.uniformNumber());
            }
        } else if (!placed && message instanceof Parameters types && types.head().equals("player_type")) {
            placed = true;
            // always draw, so the random stream does not depend on the counterpart
            Action spot = Action.move(-random.nextDouble() * 52.5, 34 - random.nextDouble() * 68);
            send.accept((counterpartMoves.isEmpty() ? spot : counterpartMoves.get(0)).command());
        } else if (message instanceof Parameters parameters && parameters.head().equals("server_param")) {
            double reach = parameters.number("player_size") + parameters.number("ball_size")
                    + parameters.number("kickable_margin");
            if (!Double.isNaN(reach)) {
                kickable = reach;
            }
            synchronous |= parameters.number("synch_mode") == 1;
        } else if (message instanceof SenseBody body) {
            stepsSinceSee++;
            view = ViewWidth.fromKey(body.viewWidth());
        } else if (message instanceof See see) {
            latestSee = see;
            stepsSinceSee = 0;
            if (!(perCycle && synchronous)) {
                decide(see, 0).forEach(action -> send.accept(action.command()));
                sendViewChange(send);
            }
        } else if (message instanceof ServerNotice notice && notice.head().equals("think")) {
            // Synchronous mode: act every cycle, as the recorded player did, on the latest view.
            synchronous = true;
            if (perCycle && latestSee != null) {
                decide(latestSee, stepsSinceSee).forEach(action -> send.accept(action.command()));
                sendViewChange(send);
            }
        }
    }

    private Destinations destinationsOf(Recognizer from) {
        return replay == Replay.TARGET ? Destinations.of(from.knowledge()) : null;
    }

    private BallWatch ballWatchOf(Recognizer from) {
        return replay == Replay.TARGET ? BallWatch.of(from.knowledge()) : null;
    }

    /** Plays as the recorded player with this number: its knowledge (when asked) and its moves. */
    private void takeRole(int unum) {
        recognizer = roles.recognizer(unum);
        destinations = destinationsOf(recognizer);
        ballWatch = ballWatchOf(recognizer);
        formation = replay == Replay.TARGET ? Formation.of(recognizer.knowledge()) : null;
        perCycle = recognizer.splitsBySeeAge();
        ImitationTeam.Counterpart counterpart = roles.counterpart(unum);
        counterpartMoves = counterpart == null ? List.of() : counterpart.moves();
        counterpartMovedInPlay = counterpart != null && counterpart.movedInPlay();
        goalie = counterpart != null && counterpart.goalie();
        placesOnce = counterpart != null && counterpart.placesOnce();
        setPlayKicks = roles.setPlayKicks(unum);
        kickOffWait = roles.kickOffWait(unum);
    }

    /**
     * With roles, the runtime repeats the kick-off move after goals only when the counterpart
     * placed itself again after time 0: a teacher that moved only before the first kick-off (the
     * real Krislet client) or never is not made to.
     */
    @Override
    public boolean repeatsKickOffMove() {
        return !withRoles || counterpartMovedInPlay;
    }

    /** The command for one see, or null when no neighbour holds a usable action. */
    String decide(See see) {
        List<Action> actions = decide(see, 0);
        return actions.isEmpty() ? null : actions.get(0).command();
    }

    /**
     * The actions for the view {@code see}, seen {@code age} cycles ago: the selected body action
     * and, as {@code validate} predicts it, the neck action of the neighbour that holds it. Empty
     * when no neighbour holds a usable action.
     */
    List<Action> decide(See see, int age) {
        Scene seen = new Scene(see.time() + age, observer,
                SceneConverter.seenObjects(see, observer, recognizer.knowledge().grid()), List.of(), null, age,
                world.snapshot(see.time() + age));
        Scene query = seen;
        List<SceneTransform> chain = transforms.get();
        if (!chain.isEmpty()) {
            for (Scene earlier : history) {
                applyAll(chain, earlier);
            }
            query = applyAll(chain, seen);
        }
        List<Neighbour> nearest = recognizer.nearest(query);
        decisions++;
        Action action = nearest.isEmpty() ? null : selector.select(nearest, random);
        if (guards.enabled() && action != null) {
            action = guard(action, seen.objects(), nearest);
        }
        trackPlayMode(seen);
        boolean leavesKickOff = leavesKickOff(seen);
        if (leavesKickOff && action != null && action.type() == ActionType.KICK) {
            action = nearestOther(nearest, candidate -> candidate.type() != ActionType.KICK);
        }
        Scene setPlayKick = leavesKickOff ? null : setPlayKick(seen, action);
        if (setPlayKick != null) {
            // the counterpart's own set-play kick, carried out from here like a neighbour's
            nearest = List.of(new Neighbour(setPlayKick, -1, 0));
            action = setPlayKick.primaryAction();
        }
        if (action != null && action.type() == ActionType.MOVE && !counterpartMoves.isEmpty()
                && !counterpartMoves.contains(action)) {
            // another player's kick-off spot: take the counterpart's own
            action = counterpartMoves.get(0);
        }
        if (action != null && action.type() == ActionType.MOVE && placesOnce) {
            if (movedInMode == playModes) {
                // placed already in this stop of play, as its counterpart placed itself once a stop: a
                // view of every step would otherwise match the placement again at every step
                action = nearestOther(nearest, candidate -> candidate.type() != ActionType.MOVE);
            } else {
                movedInMode = playModes;
            }
        }
        if (replay == Replay.TARGET) {
            Choice choice = lookFurther(new Choice(nearest, action), recognizer, query, selector, random);
            if (choice.action() != action) {
                lookedFurther++;
            }
            nearest = choice.nearest();
            action = choice.action();
            if (leavesKickOff && action != null && action.type() == ActionType.KICK) {
                action = null; // holds its place, as the teacher's other players did
            }
        }
        if (history.size() == HISTORY) {
            history.removeFirst();
        }
        double[] takerRun = setPlayKick == null && !leavesKickOff ? setPlayTakerRun(seen) : null;
        List<Action> actions = takerRun != null ? List.of(Targets.runTo(takerRun, seen.world(), ServerDefaults.MAX_POWER))
                : Validator.prediction(action, nearest, seen, replay, destinations, steering);
        if (replay == Replay.TARGET) {
            actions = keptKicks.choose(actions, seen, query, recognizer);
            if (!goalie) {
                double power = Validator.staminaSafe(ServerDefaults.MAX_POWER, seen.world());
                actions = kickFollower.follow(actions, seen.world(), seen.cycle(), power);
                if (formation != null) {
                    actions = formation.keep(actions, seen.world(), power);
                }
            }
        }
        if (ballWatch != null) {
            actions = ballWatch.watch(actions, seen.world());
            List<Action> searched = BallWatch.search(actions, seen.world());
            if (searched != actions) {
                ballSearches++;
                actions = searched;
            }
            lookBehind(actions, seen.world());
        }
        Scene made = new Scene(seen.cycle(), seen.observer(), seen.objects(), actions, null, age, seen.world());
        actions.forEach(world::sent);
        kickFollower.sent(actions, seen.world(), seen.cycle());
        history.addLast(made);
        decided.accept(made);
        if (action == null) {
            silent++;
        }
        return actions;
    }

    /**
     * The counterpart's recorded kick when the player stands at the ball in a set play of its own
     * team that has lasted as long as its counterpart waited at such set plays, or when
     * {@code chosen} kicks there sooner ({@link SetPlayKicks}): the recorded kick of that kind taken
     * nearest to where the ball lies. Null otherwise.
     */
    private Scene setPlayKick(Scene seen, Action chosen) {
        World own = seen.world();
        if (own == null) {
            return null;
        }
        if (!(own.ballDistance() <= kickable) || observer == null) { // NaN: the ball unknown
            return null;
        }
        Scene due = setPlayKicks.due(playMode, observer.side(), seen.cycle() - playModeSince, own.ballX(), own.ballY());
        return due != null || chosen == null || chosen.type() != ActionType.KICK ? due
                : setPlayKicks.taken(playMode, observer.side(), own.ballX(), own.ballY());
    }

    /** Whether this player, not its team's kick-off taker, holds back at a kick-off of its team. */
    private boolean leavesKickOff(Scene seen) {
        World own = seen.world();
        if (own == null || observer == null
                || !SetPlayKicks.KICK_OFF.equals(SetPlayKicks.ownKind(own.playMode(), observer.side()))) {
            return false;
        }
        return seen.cycle() - playModeSince < kickOffWait;
    }

    /**
     * Widens the view while the ball, unseen for longer than the teacher let it be, lies behind
     * where the neck can turn the head ({@link BallWatch#beyondView}), and narrows it back to the
     * width it had once the ball is seen: the teacher changed its view about every 15 cycles a
     * player, its scenes do not say when. Only on synchronous vision, where the player acts every
     * step on its latest see: in real time it acts on each see, and a wide view sees every third
     * cycle.
     */
    private void lookBehind(List<Action> actions, World own) {
        if (view == null || !synchronous) {
            return;
        }
        if (widenedFrom == null && view != ViewWidth.WIDE && ballWatch.beyondView(actions, own, view.degrees())) {
            widenedFrom = view;
            viewChange = ViewWidth.WIDE;
        } else if (widenedFrom != null && own != null && own.ballAge() == 0) {
            viewChange = widenedFrom;
            widenedFrom = null;
        }
    }

    private void sendViewChange(Consumer<String> send) {
        if (viewChange != null) {
            send.accept(viewChange.command());
            viewChange = null;
        }
    }

    /** Notes when the world model's play mode changed: set plays are timed from it. */
    private void trackPlayMode(Scene seen) {
        World own = seen.world();
        if (own != null && !own.playMode().equals(playMode)) {
            playMode = own.playMode();
            playModeSince = seen.cycle();
            playModes++;
        }
    }

    /**
     * Where to run as the taker of a set play of the player's own team, under target replay: the
     * ball, when the player's world model makes it its team's nearest to it and it is not yet at
     * it. The teacher took every one of its set plays (HELIOS base: all its kick-offs); a snapshot
     * of the view does not say who should, and two imitators 6 m from the ball could each match
     * teacher scenes of a player who waited there. Null otherwise.
     */
    private double[] setPlayTakerRun(Scene seen) {
        World own = seen.world();
        if (replay != Replay.TARGET || own == null || observer == null
                || SetPlayKicks.ownKind(own.playMode(), observer.side()) == null
                || !own.nearestOfItsTeamToBall() || own.ballDistance() <= kickable) {
            return null;
        }
        return Targets.intercept(own);
    }

    private Action guard(Action chosen, List<SeenObject> seen, List<Neighbour> nearest) {
        Action action = chosen;
        if (action.type() == ActionType.KICK && !ballWithin(seen, kickable)) {
            kickGuarded++;
            action = nearestOther(nearest, candidate -> candidate.type() != ActionType.KICK);
            if (action == null) {
                return null;
            }
        }
        unchanged = action.equals(lastAction) && seen.equals(lastSeen) ? unchanged + 1 : 0;
        if (unchanged + 1 >= guards.stuckSees()) {
            Action stuck = action;
            Action other = nearestOther(nearest, candidate -> !candidate.equals(stuck)
                    && (candidate.type() != ActionType.KICK || ballWithin(seen, kickable)));
            if (other != null) {
                stuckGuarded++;
                action = other;
                unchanged = 0;
            }
        }
        lastAction = action;
        lastSeen = seen;
        return action;
    }

    /** The primary action of the nearest neighbour whose action passes, or null. */
    private static Action nearestOther(List<Neighbour> nearest, Predicate<Action> wanted) {
        for (Neighbour neighbour : nearest) {
            Action action = neighbour.scene().primaryAction();
            if (action != null && wanted.test(action)) {
                return action;
            }
        }
        return null;
    }

    /** The neighbours a decision works from and the action chosen among them (null: none). */
    public record Choice(List<Neighbour> nearest, Action action) {
    }

    /**
     * Under target replay, {@code choice} unless it sends no body command a player in play carries
     * out (none, only the neck, or a move: a move belongs to the counterpart's placements, which
     * the brain handles apart, and the server ignores one in play), while the recognizer's k is
     * below {@link #LOOK_FURTHER}: then the selector's choice among the {@link #LOOK_FURTHER}
     * nearest neighbours that send such a command, if any.
     */
    public static Choice lookFurther(Choice choice, Recognizer recognizer, Scene query, ActionSelector selector,
                                     RandomGenerator random) {
        if (moves(choice.action()) || recognizer.k() >= LOOK_FURTHER) {
            return choice;
        }
        List<Neighbour> further = recognizer.nearest(query, LOOK_FURTHER).stream()
                .filter(neighbour -> moves(neighbour.scene().primaryAction())).toList();
        Action instead = further.isEmpty() ? null : selector.select(further, random);
        return instead == null ? choice : new Choice(further, instead);
    }

    private static boolean moves(Action action) {
        return action != null && action.type().worldChanging() && action.type() != ActionType.MOVE;
    }

    private static boolean ballWithin(List<SeenObject> seen, double reach) {
        for (SeenObject object : seen) {
            if (object.kind() == ObjectKind.BALL && object.distance() <= reach) {
                return true;
            }
        }
        return false;
    }

    private static Scene applyAll(List<SceneTransform> chain, Scene scene) {
        for (SceneTransform transform : chain) {
            scene = transform.apply(scene);
        }
        return scene;
    }

    /**
     * Tells {@code listener} of every scene this brain builds from a see, with the action it chose
     * (none when silent): the scenes a log of the same traffic converts to.
     */
    public void onScene(Consumer<Scene> listener) {
        decided = Objects.requireNonNull(listener, "listener");
    }

    /** Sees answered so far, and how many of them got no action. */
    public long decisions() {
        return decisions;
    }

    public long silent() {
        return silent;
    }

    @Override
    public Map<String, Long> counters() {
        Map<String, Long> counters = new LinkedHashMap<>();
        counters.put("decisions", decisions);
        counters.put("silent", silent);
        counters.put("looked_further", lookedFurther);
        counters.put("kicks_kept_instead", keptKicks.kept());
        counters.put("kicks_shot_instead", keptKicks.shots());
        counters.put("kicks_handed_over", keptKicks.handedOver());
        counters.put("ball_searches", ballSearches);
        counters.put("kicks_followed", kickFollower.follows());
        counters.put("formation_runs", formation == null ? 0 : formation.runs());
        if (guards.enabled()) {
            counters.put("guard.kick_out_of_reach", kickGuarded);
            counters.put("guard.stuck", stuckGuarded);
        }
        return counters;
    }
}
