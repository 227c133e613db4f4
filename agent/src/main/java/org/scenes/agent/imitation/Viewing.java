package org.scenes.agent.imitation;

import java.util.Map;
import java.util.Random;
import java.util.function.Consumer;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.Parameters;
import org.scenes.internal.protocol.ViewWidth;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/**
 * Gives a player the view its teacher played with. A librcsc team such as HELIOS base asks for
 * synchronous vision and narrows its view near the ball, so its scenes at the ball are mostly of
 * sees taken in the same step; an imitator on the server's default view decides there on views a
 * step old, which its teacher rarely kicked on. Right after its placement (the first
 * {@code player_type}) the player sends {@code (synch_see)} when the server is synchronous, then
 * {@code (change_view WIDTH)}; the brain itself is untouched.
 */
public final class Viewing implements Brain {
    private final Brain inner;
    private final ViewWidth width;
    private final MessageParser parser = new MessageParser();
    private boolean synchronous;
    private boolean asked;

    private Viewing(Brain inner, ViewWidth width) {
        this.inner = inner;
        this.width = width;
    }

    /** The brains of {@code factory} asking for {@code width}; a null width leaves them as they are. */
    public static BrainFactory with(BrainFactory factory, ViewWidth width) {
        if (width == null) {
            return factory;
        }
        return new BrainFactory() {
            @Override
            public Brain create(String team, Random random) {
                return new Viewing(factory.create(team, random), width);
            }

            @Override
            public boolean goalie(int unum) {
                return factory.goalie(unum);
            }
        };
    }

    /** The imitating brain {@code brain} is or asks the view for, or null when it holds none. */
    public static ImitationBrain imitation(Brain brain) {
        Brain unwrapped = brain instanceof Viewing viewing ? viewing.inner : brain;
        return unwrapped instanceof ImitationBrain imitation ? imitation : null;
    }

    @Override
    public boolean repeatsKickOffMove() {
        return inner.repeatsKickOffMove();
    }

    @Override
    public Map<String, Long> counters() {
        return inner.counters();
    }

    @Override
    public void receive(String message, Consumer<String> send) {
        inner.receive(message, send);
        if (asked || !message.startsWith("(server_param") && !message.startsWith("(player_type")) {
            return;
        }
        Message parsed = parser.parse(message);
        if (parsed instanceof Parameters parameters && parameters.head().equals("server_param")) {
            synchronous = parameters.number("synch_mode") == 1;
        } else if (parsed instanceof Parameters parameters && parameters.head().equals("player_type")) {
            asked = true;
            if (synchronous) {
                send.accept("(synch_see)");
            }
            send.accept(width.command());
        }
    }
}
