package org.scenes.simulator.teacher;

import org.scenes.api.Side;
import org.scenes.internal.protocol.Hear;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.VisualObject;

/**
 * What a teacher knows: its side, the play mode and the latest {@code see}, read from the
 * server's text with core's {@link MessageParser}, the same parser the log converter uses.
 */
final class Perception {
    private final MessageParser parser = new MessageParser();
    Side side = Side.LEFT;
    String playMode = "before_kick_off";
    /** The latest see, null before the first. */
    See see;

    /** Reads one server message; returns true when it was a see (the moment teachers decide). */
    boolean read(String text) {
        Message message = parser.parse(text);
        if (message instanceof InitReply reply && reply.side() != null) {
            side = reply.side();
            playMode = reply.playMode();
        } else if (message instanceof Hear hear && hear.speaker() == Hear.Speaker.REFEREE) {
            playMode = hear.text();
        } else if (message instanceof See seen) {
            see = seen;
            return true;
        }
        return false;
    }

    /** A visible object by short name ({@code b}, {@code g r}), null when not in the last see. */
    VisualObject find(String name) {
        return find(see, name);
    }

    /** An object of {@code see} by short name, null when not seen or when there is no see. */
    static VisualObject find(See see, String name) {
        if (see == null) {
            return null;
        }
        for (VisualObject object : see.objects()) {
            if (object.name().equals(name)) {
                return object;
            }
        }
        return null;
    }

    VisualObject ball() {
        return find("b");
    }

    VisualObject opponentGoal() {
        return opponentGoal(see, side);
    }

    static VisualObject opponentGoal(See see, Side side) {
        return find(see, side == Side.LEFT ? "g r" : "g l");
    }

    VisualObject ownGoal() {
        return find(side == Side.LEFT ? "g l" : "g r");
    }
}
