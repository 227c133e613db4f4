package org.scenes.internal.protocol;

import java.util.Locale;
import org.scenes.api.ActionType;

/**
 * Every command a player client sends after {@code init}, with the scene action it becomes
 * ({@link ActionType#NONE} for commands that are not scene actions, such as {@code say}).
 */
public enum CommandType {
    DASH(ActionType.DASH),
    TURN(ActionType.TURN),
    KICK(ActionType.KICK),
    TURN_NECK(ActionType.TURN_NECK),
    CATCH(ActionType.CATCH),
    MOVE(ActionType.MOVE),
    TACKLE(ActionType.TACKLE),
    SAY(ActionType.NONE),
    CHANGE_VIEW(ActionType.NONE),
    SENSE_BODY(ActionType.NONE),
    SCORE(ActionType.NONE),
    BYE(ActionType.NONE),
    POINTTO(ActionType.NONE),
    ATTENTIONTO(ActionType.NONE),
    CHANGE_FOCUS(ActionType.NONE),
    DONE(ActionType.NONE),
    SYNCH_SEE(ActionType.NONE),
    GAUSSIAN_SEE(ActionType.NONE),
    EAR(ActionType.NONE),
    CLANG(ActionType.NONE),
    COMPRESSION(ActionType.NONE),
    /** rcssserver 19's kick of another kind; not a scene action (a scene's kick would replay it as a plain kick). */
    LONG_KICK(ActionType.NONE);

    private static final CommandType[] VALUES = values();

    private final ActionType action;
    private final String key;

    CommandType(ActionType action) {
        this.action = action;
        this.key = name().toLowerCase(Locale.ROOT);
    }

    /** The scene action this command becomes, {@link ActionType#NONE} when none. */
    public ActionType action() {
        return action;
    }

    /** Whether rcssserver executes at most one such command a cycle: dash, turn, kick, catch, tackle, move. */
    public boolean body() {
        return action != ActionType.NONE && action != ActionType.TURN_NECK;
    }

    /** The protocol word: {@code turn_neck}, {@code pointto}. */
    public String key() {
        return key;
    }

    /** The command with this protocol word, or null. */
    public static CommandType fromKey(String key) {
        for (CommandType type : VALUES) {
            if (type.key.equals(key)) {
                return type;
            }
        }
        return null;
    }
}
