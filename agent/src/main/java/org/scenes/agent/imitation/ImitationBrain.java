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
 */
public final class ImitationBrain implements Brain {
    private final String team;
    private final Recognizer recognizer;
    private final ActionSelector selector;
    private final List<SceneTransform> transforms;
    private final Random random;
    private final MessageParser parser = new MessageParser();
    private Observer observer = Observer.UNKNOWN;
    private boolean placed;
    private long decisions;
    private long silent;

    public ImitationBrain(String team, Recognizer recognizer, ActionSelector selector, List<SceneTransform> transforms,
                          Random random) {
        this.team = Objects.requireNonNull(team, "team");
        this.recognizer = Objects.requireNonNull(recognizer, "recognizer");
        this.selector = Objects.requireNonNull(selector, "selector");
        this.transforms = List.copyOf(transforms);
        this.random = Objects.requireNonNull(random, "random");
    }

    /** A factory sharing one recognizer (it is thread-safe) with a fresh selector and transforms per player. */
    public static BrainFactory factory(Recognizer recognizer, Supplier<ActionSelector> selectors,
                                       Supplier<List<SceneTransform>> transforms) {
        return (team, random) -> new ImitationBrain(team, recognizer, selectors.get(), transforms.get(), random);
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
        Scene scene = new Scene(see.time(), observer,
                SceneConverter.seenObjects(see, observer, recognizer.knowledge().grid()), List.of());
        for (SceneTransform transform : transforms) {
            scene = transform.apply(scene);
        }
        List<Neighbour> nearest = recognizer.nearest(scene);
        decisions++;
        Action action = nearest.isEmpty() ? null : selector.select(nearest, random);
        if (action == null) {
            silent++;
            return null;
        }
        return action.command();
    }

    /** Sees answered so far, and how many of them got no action. */
    public long decisions() {
        return decisions;
    }

    public long silent() {
        return silent;
    }
}
