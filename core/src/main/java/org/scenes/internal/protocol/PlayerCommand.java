package org.scenes.internal.protocol;

import org.scenes.api.Action;
import org.scenes.api.ActionType;

/**
 * A command from the player: numeric arguments in {@code first}/{@code second} ({@code NaN} when
 * absent), word arguments ({@code say} message, {@code change_view} width and quality,
 * {@code pointto off}, {@code attentionto our 5}, a {@code tackle} foul flag, the nested lists of
 * {@code ear} and {@code clang}, the legs of a two-leg {@code dash} such as {@code (l 100 0) (r 80 10)})
 * in {@code text}. A two-leg dash has the legs' mean power and direction in {@code first}/{@code second}.
 *
 * @param wellFormed whether the arguments have the form the server accepts; the server answers an
 *                   ill-formed command (e.g. {@code (dash)}) with {@code (error illegal_command_form)}
 *                   and does not execute it
 */
public record PlayerCommand(CommandType type, double first, double second, String text, boolean wellFormed)
        implements Message {

    @Override
    public String head() {
        return type.key();
    }

    @Override
    public boolean fromClient() {
        return true;
    }

    /** The scene action, or null when the command is not an action or was ill-formed. */
    public Action toAction() {
        ActionType action = type.action();
        if (action == ActionType.NONE || !wellFormed) {
            return null;
        }
        if (type == CommandType.TACKLE) {
            Boolean foul = foulFlag(text);
            return new Action(action, first, foul == null ? Double.NaN : foul ? 1 : 0);
        }
        return new Action(action, first, second);
    }

    /** A tackle's foul flag: true for {@code on}/{@code true}, false for {@code off}/{@code false}, null otherwise. */
    public static Boolean foulFlag(String word) {
        return switch (word) {
            case "on", "true" -> Boolean.TRUE;
            case "off", "false" -> Boolean.FALSE;
            default -> null;
        };
    }
}
