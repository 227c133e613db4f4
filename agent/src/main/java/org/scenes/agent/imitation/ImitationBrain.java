package org.scenes.agent.imitation;

import java.util.List;
import java.util.Objects;
import java.util.Random;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.scenes.agent.Brain;
import org.scenes.agent.BrainFactory;
import org.scenes.convert.SceneConverter;
import org.scenes.match.ActionSelector;
import org.scenes.match.Neighbour;
import org.scenes.match.Recognizer;
import org.scenes.match.SceneTransform;
import org.scenes.protocol.InitReply;
import org.scenes.protocol.Message;
import org.scenes.protocol.MessageParser;
import org.scenes.protocol.See;
import org.scenes.scene.Action;
import org.scenes.scene.Observer;
import org.scenes.scene.Scene;

/**
 * The imitating player: every {@code see} becomes a scene exactly as the converter makes one
 * from a log ({@link SceneConverter#seenObjects}, the knowledge base's grid, the same
 * transforms), the recognizer finds the nearest stored scenes and the selector picks the action,
 * which is sent as its command. Before kick-off it moves to a random spot of its own half: the
 * recorded moves come before the first see, so no scene holds one.
 *
 * <p>Transforms such as {@code memory} remember earlier scenes with the action taken in them.
 * In validation that is the recorded action; here it is the action this brain chose, which is
 * known only after the query: so each decision runs fresh transforms over the last
 * {@link #HISTORY} scenes, each with its chosen action, and then over the new scene.
 */
public final class ImitationBrain implements Brain {
    /** Scenes replayed through the transforms before each query; enough for one-step memory and more. */
    static final int HISTORY = 8;

    private final String team;
    private final Recognizer recognizer;
    private final ActionSelector selector;
    private final Supplier<List<SceneTransform>> transforms;
    private final java.util.ArrayDeque<Scene> history = new java.util.ArrayDeque<>(HISTORY);
    private final Random random;
    private final MessageParser parser = new MessageParser();
    private Observer observer = Observer.UNKNOWN;
    private boolean placed;
    private long decisions;
    private long silent;

    /**
     * @param transforms makes a fresh chain of the scene transforms the knowledge base was built
     *                   with
     */
    public ImitationBrain(String team, Recognizer recognizer, ActionSelector selector,
                          Supplier<List<SceneTransform>> transforms, Random random) {
        this.team = Objects.requireNonNull(team, "team");
        this.recognizer = Objects.requireNonNull(recognizer, "recognizer");
        this.selector = Objects.requireNonNull(selector, "selector");
        this.transforms = Objects.requireNonNull(transforms, "transforms");
        this.random = Objects.requireNonNull(random, "random");
    }

    /** A factory sharing one recognizer (it is thread-safe) with a fresh selector and transforms per player. */
    public static BrainFactory factory(Recognizer recognizer, Supplier<ActionSelector> selectors,
                                       Supplier<List<SceneTransform>> transforms) {
        return (team, random) -> new ImitationBrain(team, recognizer, selectors.get(), transforms, random);
    }

    @Override
    public void receive(String text, Consumer<String> send) {
        Message message = parser.parse(text);
        if (message instanceof InitReply reply && reply.side() != null) {
            observer = new Observer(team, reply.side(), reply.uniformNumber());
        } else if (!placed && text.startsWith("(player_type")) {
            placed = true;
            send.accept(Action.move(-random.nextDouble() * 52.5, 34 - random.nextDouble() * 68).command());
        } else if (message instanceof See see) {
            String command = decide(see);
            if (command != null) {
                send.accept(command);
            }
        }
    }

    /** The command for one see, or null when no neighbour holds a usable action. */
    String decide(See see) {
        Scene seen = new Scene(see.time(), observer,
                SceneConverter.seenObjects(see, observer, recognizer.knowledge().grid()), List.of());
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
        if (history.size() == HISTORY) {
            history.removeFirst();
        }
        history.addLast(new Scene(seen.cycle(), seen.observer(), seen.objects(),
                action == null ? List.of() : List.of(action)));
        if (action == null) {
            silent++;
            return null;
        }
        return action.command();
    }

    private static Scene applyAll(List<SceneTransform> chain, Scene scene) {
        for (SceneTransform transform : chain) {
            scene = transform.apply(scene);
        }
        return scene;
    }

    /** Sees answered so far, and how many of them got no action. */
    public long decisions() {
        return decisions;
    }

    public long silent() {
        return silent;
    }

    /** What this brain counts of itself, by name, for the runtime's report. */
    public java.util.Map<String, Long> counters() {
        java.util.Map<String, Long> counters = new java.util.LinkedHashMap<>();
        counters.put("decisions", decisions);
        counters.put("silent", silent);
        return counters;
    }
}
