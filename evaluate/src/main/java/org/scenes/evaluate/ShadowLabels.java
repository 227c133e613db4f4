package org.scenes.evaluate;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.scenes.api.Action;
import org.scenes.api.Scene;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.simulator.Brain;

/**
 * DAgger's labels for one imitating player: each scene the imitator built from a see, with the
 * actions its shadow teacher sent in reply to that same see: its first body command and its first
 * {@code turn_neck}, sent after the see and before the next one (the pairing scene conversion uses
 * for logs). A scene whose see the shadow answered with no body command is left out; of several
 * scenes built from one see (a paced imitator deciding again on an old see) the first is kept.
 *
 * <p>Imitator and shadow are wrapped separately ({@link #imitator}, {@link #shadow}), each view
 * numbering the sees it is given; both are fed the same messages, so a see has the same number in
 * both whichever is fed first. A scene belongs to the latest see its imitator was given: an
 * imitator (paced or not) builds its scene from its latest see.
 */
final class ShadowLabels {
    private final MessageParser parser = new MessageParser();
    /** Per see, from see 1 at index 0: the scene built from it, or null. */
    private final List<Scene> scenes = new ArrayList<>();
    /** Per see, from see 1 at index 0: the shadow's body command and turn_neck in reply, either null. */
    private final List<Action[]> replies = new ArrayList<>();
    private int imitatorSees;
    private int shadowSees;
    private int unum;

    /** The imitator's brain, its sees numbered; its scenes go to {@link #built}. */
    Brain imitator(Brain brain) {
        return new Brain() {
            @Override
            public void receive(String message, Consumer<String> send) {
                if (message.startsWith("(see ")) {
                    imitatorSees++;
                } else if (message.startsWith("(init ")
                        // its own parser: the shadow's replies may be parsed on another thread
                        && parse(new MessageParser(), message) instanceof InitReply init) {
                    unum = init.uniformNumber();
                }
                brain.receive(message, send);
            }

            @Override
            public boolean repeatsKickOffMove() {
                return brain.repeatsKickOffMove();
            }
        };
    }

    /**
     * The shadow teacher's brain, its sees numbered and its commands recorded as the replies to
     * them; a {@link LateShadow}'s late commands are the replies to the see before the message.
     */
    Brain shadow(Brain brain) {
        return new Shadow(brain);
    }

    private final class Shadow implements Brain, LateShadow {
        private final Brain brain;

        Shadow(Brain brain) {
            this.brain = brain;
        }

        @Override
        public void receive(String message, Consumer<String> send) {
            collect(send);
            if (message.startsWith("(see ")) {
                shadowSees++;
            }
            brain.receive(message, command -> {
                reply(command);
                send.accept(command);
            });
        }

        @Override
        public void collect(Consumer<String> send) {
            if (brain instanceof LateShadow late) {
                late.collect(command -> {
                    reply(command);
                    send.accept(command);
                });
            }
        }

        @Override
        public boolean repeatsKickOffMove() {
            return brain.repeatsKickOffMove();
        }
    }

    /** A scene the imitator built, from its latest see. */
    void built(Scene scene) {
        if (imitatorSees == 0) {
            return;
        }
        while (scenes.size() < imitatorSees) {
            scenes.add(null);
        }
        if (scenes.get(imitatorSees - 1) == null) {
            scenes.set(imitatorSees - 1, scene);
        }
    }

    private void reply(String text) {
        if (shadowSees == 0) {
            return; // the kick-off move before any see, as conversion drops it
        }
        if (!(parse(parser, text) instanceof PlayerCommand command) || command.toAction() == null) {
            return;
        }
        while (replies.size() < shadowSees) {
            replies.add(new Action[2]);
        }
        Action[] reply = replies.get(shadowSees - 1);
        int slot = command.type() == CommandType.TURN_NECK ? 1 : command.type().body() ? 0 : -1;
        if (slot >= 0 && reply[slot] == null) {
            reply[slot] = command.toAction();
        }
    }

    /** The message, or null when it does not parse. */
    private static Message parse(MessageParser parser, String text) {
        try {
            return parser.parse(text);
        } catch (RuntimeException e) {
            return null;
        }
    }

    /** The uniform number the server gave the imitating player (0 before its init was answered). */
    int unum() {
        return unum;
    }

    /** The scenes built so far with the shadow's replies as their actions, in see order. */
    List<Scene> labelled() {
        List<Scene> out = new ArrayList<>();
        for (int i = 0; i < Math.min(scenes.size(), replies.size()); i++) {
            Scene scene = scenes.get(i);
            Action[] reply = replies.get(i);
            if (scene == null || reply[0] == null) {
                continue;
            }
            List<Action> actions = reply[1] == null ? List.of(reply[0]) : List.of(reply[0], reply[1]);
            out.add(new Scene(scene.cycle(), scene.observer(), scene.objects(), actions, null, scene.seeAge(),
                    scene.world()));
        }
        return out;
    }
}
