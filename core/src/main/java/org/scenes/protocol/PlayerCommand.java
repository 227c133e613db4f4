package org.scenes.protocol;

import org.scenes.scene.Action;
import org.scenes.scene.ActionType;

/**
 * A command from the player: numeric arguments in {@code first}/{@code second} ({@code NaN} when
 * absent), word arguments ({@code say} message, {@code change_view} width and quality,
 * {@code pointto off}, {@code attentionto our 5}, a {@code tackle} foul flag, the nested lists of
 * {@code ear} and {@code clang}) in {@code text}.
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
        return new Action(action, first, second);
    }
}
